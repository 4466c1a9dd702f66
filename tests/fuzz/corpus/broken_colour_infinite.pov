// error: 3:1: the light's colour is infinite
// A light of infinite colour made every lit pixel NaN: a black frame.
light_source { <0, 10, 0>, rgb <1, 1, 1> * 1e300 * 1e300 }

