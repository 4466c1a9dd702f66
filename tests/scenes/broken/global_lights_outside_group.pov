// error: 4:41: global_lights belongs in a light_group, not in this object
// povray: line 4: Parse Error: No matching } in 'union', global_lights found
// (POV-Ray reads global_lights only in a light_group.)
union { sphere { 0, 1 } sphere { x, 1 } global_lights on }
