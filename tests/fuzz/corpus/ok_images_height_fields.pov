// Fuzz seed: images a scene reads (POV-Ray's include folder holds these):
// image_map of PNG and POT, bump_map, height_fields of PNG, POT and a
// function.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 2, -4> look_at 0 }
light_source { <-3, 5, -4> rgb 1 }
sphere { <-1, 0.5, 0>, 0.5 pigment { image_map { png "plasma2.png" interpolate 2 map_type 1 } } }
sphere { <1, 0.5, 0>, 0.5 pigment { image_map { png "povmap.png" once filter all 0.3 transmit 2, 0.5 } } }
box { <-0.5, 0, -0.5>, <0.5, 1, 0.5>
  pigment { image_map { gif "mtmand.pot" interpolate 4 gamma srgb } }
  normal { bump_map { png "bumpmap_.png" bump_size 2 use_index } }
}
height_field { png "Mount1.png" smooth water_level 0.1 translate <-0.5, -1, -0.5> scale <3, 0.5, 3> pigment { rgb 0.8 } }
height_field { pot "mtmand.pot" translate <-0.5, -1.2, 1> pigment { rgb y } }
height_field { function 12, 12 { pigment { bozo color_map { [0 rgb 0] [1 rgb 1] } } } translate <1, -1, 1> pigment { rgb x } }
