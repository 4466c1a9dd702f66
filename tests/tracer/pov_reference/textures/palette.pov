// hexant against POV-Ray 3.7: an image_map of a palette PNG whose entries
// take their own filter and transmit (filter N, AMOUNT and transmit N,
// AMOUNT), set before and after `transmit all` / `filter all` (the later
// wins, entry by entry), bilinear too, over a checker that shows through;
// the walls move with clock. palette.png: 8 x 6, 4 bits an index into 12
// entries, entry 0 half clear (make_images.py). (No shadows: hexant's
// shadows through a transparent pigment are POV-Ray's, but these walls
// cast none, to keep the test on the image.)
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1, -6> look_at <0, 0.3, 0> angle 50 }
light_source { <-5, 8, -6> color rgb 1 }
background { rgb <0.1, 0.1, 0.2> }
plane { z, 1 pigment { checker rgb 1, rgb <0.2, 0.3, 0.1> scale 0.3 } }
// One entry clear, another filtering; the others as the file has them.
box { <-3, -1, 0>, <0, 1.5, 0.01>
  pigment { image_map { png "palette.png" once transmit 5, 1 filter 2, 0.8 }
            scale <3, 2.5, 1> translate <-3, -1, 0> translate y * 0.5 * clock }
  finish { ambient 0.3 }
  no_shadow
}
// transmit all after one entry's (all wins), then entries' own after it;
// filter all before one entry's; bilinear.
box { <0, -1, 0>, <3, 1.5, 0.01>
  pigment { image_map { png "palette.png" interpolate 2 transmit 3, 1 transmit all 0.4
                        transmit 7, 1 transmit 8 0 filter all 0.5 filter 9, 0 }
            scale <3, 2.5, 1> translate <0, -1, 0> translate x * -0.4 * clock }
  finish { ambient 0.3 }
  no_shadow
}
