// POV-Ray 3.7 warns "Scale X by 0.0. Changed to 1.0" and renders; so does hexant.
sphere { 0, 1 scale 0 }

