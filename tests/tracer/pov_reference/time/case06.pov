// Case 06 of ../shared/cases (a countdown driven by frame_number), with
// spheres in place of the text digits until hexant has text: the tens
// sphere exists while Count > 9 (frames 1 and 2 of 8), and the ones
// sphere's size follows the ones digit.
#version 3.7;
global_settings { assumed_gamma 1.0 }

#declare Count = 12 - frame_number;
#declare Tens  = int(Count/10);
#declare Ones  = Count - Tens*10;

camera { location <0.6, 0.4, -3> look_at <0.6, 0.4, 0> angle 40 }
light_source { <2, 3, -5> color rgb 1 }
background { color rgb <0.1, 0.1, 0.3> }

union {
  #if (Count > 9)
    sphere { <0.25, 0.35, 0>, 0.1 + 0.1 * Tens }
  #end
  sphere { <0.85, 0.35, 0>, 0.05 + 0.03 * Ones }
  pigment { color rgb <1, 0.8, 0.2> }
}
