camera { perspective location -5*z look_at 0 }
sphere { 0, 1 pigment { rgb 1 } }
