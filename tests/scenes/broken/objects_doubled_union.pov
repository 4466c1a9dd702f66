// error: 8:14: this object would make 1048576 objects
// (issue 45) once: a union doubled 30 times asked for 2^30 spheres (6.9 GB
// before it was stopped). Refused where the doubling passes the default limit
// of 10^6, before anything walks its members.
camera { location <0, 0, -5> look_at 0 }
#declare U = sphere { 0, 0.1 }
#for (I, 1, 30)
#declare U = union { object { U } object { U translate x * 0.001 } }
#end
object { U pigment { rgb 1 } }
