// What POV-Ray 3.7 tolerates and hexant must too: no comma between a box's
// corners or a sphere's centre and radius, no semicolon after an object
// #declare, #local at file level, #undef of a name never declared (a warning),
// a name re-declared with another type, several directives on one line,
// nested block comments, names that start like a keyword (sphere_radius) or
// differ from one only in case (Sphere).
#version 3.7;
global_settings { assumed_gamma 1.0 }

box { <0, 0, 0> <1, 1, 1> }
sphere { <0, 0, 0> 1 }
cylinder { <0, 0, 0> <0, 1, 0> 0.5 }
cone { <0, 0, 0> 1 <0, 2, 0> 0 }
#declare Thing = sphere { 0, 1 }
#declare Thing = 3;                  // a float now
#local Here = 2;                     // at file level #local is #declare
#undef Never_Declared
#if (Thing + Here != 5) #error "redeclared" #end #declare A = 1; #declare B = A + 1;
/* a /* nested */ comment */
#declare sphere_radius = 0.5;        // keywords are lower case; this is a name
#declare Sphere = sphere { 0, sphere_radius }
object { Sphere }
// Vectors as POV-Ray reads them: commas left out, and a trailing comma.
#declare Spaced = < -1 2 3 >;
#declare Trailing = rgb <0.2, 0.1, 0.5,>;
#if (Spaced.x != -1 | Spaced.z != 3 | Trailing.blue != 0.5) #error "vector commas misread" #end
// A 2-component colour is padded with 0, as POV-Ray pads it.
#declare Short = rgb <1, 0.5>;
#if (Short.blue != 0 | Short.green != 0.5) #error "a short colour misread" #end
