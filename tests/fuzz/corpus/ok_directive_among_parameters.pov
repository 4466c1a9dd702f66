// POV-Ray reads directives among a shape's parameters (issue 16).
#declare Flip = 1;
smooth_triangle {
  #if (Flip) <0,0,0>, -y, <1,0,0>, -y, <0,1,0>, -y
  #else <0,0,0>, y, <1,0,0>, y, <0,1,0>, y #end
  pigment { rgb 1 }
}

