// five-objects.scene written for POV-Ray 3.7, for timing the two on the same scene (issue 11):
//   povray +W1024 +H768 -A -D +MV3.7 +Ofive-objects.png five-objects.pov
// POV-Ray's coordinates are left-handed, so its picture is Prism's mirrored left to right. Its
// camera angle is horizontal: 2 atan(tan(50/2) 4/3) = 63.8 degrees for Prism's vertical 50.
#version 3.7;
global_settings { max_trace_level 5 assumed_gamma 1.0 ambient_light rgb 1 }
background { rgb <0.1, 0.1, 0.15> }
camera { perspective location <0, 2, -8> look_at <0, 1, 0> right x * 4 / 3 angle 63.8 }
light_source { <-5, 8, -6> color rgb 0.8 }
light_source { <6, 6, -4> color rgb 0.5 }

plane { y, 0 pigment { rgb 0.7 } finish { ambient 0.1 diffuse 0.9 reflection 0.3 } }
sphere { <-2, 1, 0.5>, 1 pigment { rgb 0.9 }
         finish { ambient 0.1 diffuse 0.1 specular 0.8 roughness 0.01 reflection 0.8 } }
sphere { <0.3, 1, -1>, 1 pigment { rgbf <1, 1, 1, 0.9> }
         finish { ambient 0 diffuse 0 specular 1 roughness 0.005 } interior { ior 1.5 } }
sphere { <2.4, 0.7, 0.8>, 0.7 pigment { rgb <0.9, 0.2, 0.2> }
         finish { ambient 0.1 diffuse 0.9 specular 0.5 roughness 0.02 } }
sphere { <-0.4, 0.5, 2.2>, 0.5 pigment { rgb <0.2, 0.3, 0.9> }
         finish { ambient 0.1 diffuse 0.9 specular 0.5 roughness 0.02 } }
