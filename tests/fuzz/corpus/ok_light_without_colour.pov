// A light_source with no colour: POV-Ray 3.7 accepts it and makes it white
// (checked with povray 3.7: it renders the sphere lit). The colour may also
// follow without a comma, and modifiers may follow the position directly.
light_source { <0, 10, -10> }
light_source { <0, 10, -10> shadowless }
light_source { <0, 10, -10> translate x }
light_source { <0, 10, -10> rgb <1, 0.5, 0.5> }
sphere { 0, 1 }

