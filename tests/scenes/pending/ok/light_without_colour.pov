// A light_source with no colour: POV-Ray 3.7 accepts it (the colour
// defaults to white); hexant check reports "expected a parameter".
light_source { <0, 10, -10> }
sphere { 0, 1 }
