// error: 3:11: polygon's point count 1.0000000000000001e+300 is out of range 3 to 100000000
// (issue 17, the reliability cases) once: a count of 1e300 cast to an integer.
polygon { 1e300, <0,0>, <1,0>, <0,1> }
