// scenes/showcase.toml for POV-Ray 3.7: the same objects, lights, resolution and trace depth,
// for timing whitted against the classic renderer (benches/povray/compare.sh).
//
// whitted is right-handed (z towards the viewer), POV-Ray left-handed (z into the screen):
// every z below is the scene file's z negated, and each rotation is written as the matrix
// F·R·F with F = diag(1, 1, −1).
//
// Shading is matched as closely as the two models allow. whitted: I = ρa·I_m + Σ I_p(ρd n·s +
// ρs (r·v)^f) + kr·I_r + kt·I_t, no gamma. Here: pigment = ρd, diffuse 1, ambient = ρa/ρd per
// channel (POV multiplies ambient by the pigment), phong ρs with phong_size f (Phong's r·v),
// reflection kr, transmit kt with the interior's ior. assumed_gamma 1 and File_Gamma=1 on the
// command line: both programs write linear intensities.
//
// Render as compare.sh does:
//   povray +Ishowcase.pov +O/tmp/pov.png +W1920 +H1080 -D +FN File_Gamma=1.0 -GA

global_settings {
  assumed_gamma 1.0
  max_trace_level 6      // primary ray + whitted's max_depth = 5 bounces
  adc_bailout 0.001      // whitted's min_weight
  ambient_light rgb 1    // [ambient] intensity = 1
}

#declare Aspect = image_width / image_height;
camera {
  perspective
  location <0.0, 2.4, -8.5>
  look_at <0.0, 0.9, 0.0>
  up y
  right x * Aspect
  // whitted's fov is the vertical angle (45°); POV-Ray's angle is the horizontal one
  angle 2 * degrees(atan(tan(radians(45 / 2)) * Aspect))
}

background { rgb <0.05, 0.06, 0.10> }

light_source { <-6.0, 9.0, -6.0> color rgb <0.75, 0.65, 0.55> }  // warm key light
light_source { < 7.0, 5.0, -4.0> color rgb <0.30, 0.38, 0.55> }  // cool fill light

#declare Floor = texture {
  pigment { rgb 1 }
  finish { ambient 0.08 diffuse 0.62 phong 0.1 phong_size 10 }
}
#declare Mirror = texture {
  pigment { rgb <0.25, 0.05, 0.05> }
  finish { ambient rgb <0.16, 0.2, 0.2> diffuse 1 phong 0.5 phong_size 120 reflection 0.65 }
}
#declare Glass = material {
  texture {
    pigment { rgbt <1, 1, 1, 0.88> }
    finish { ambient 0 diffuse 0.1667 phong 0.7 phong_size 250 reflection 0.08 }
  }
  interior { ior 1.5 }
}
#declare Blue = texture {
  pigment { rgb <0.15, 0.3, 0.7> }
  finish { ambient rgb <0.133333, 0.133333, 0.142857> diffuse 1 phong 0.2 phong_size 30 }
}
#declare Gold = texture {
  pigment { rgb <0.7, 0.5, 0.12> }
  finish { ambient rgb <0.142857, 0.16, 0.166667> diffuse 1 phong 0.18 phong_size 60 }
}
#declare Green = texture {
  pigment { rgb <0.2, 0.62, 0.25> }
  finish { ambient rgb <0.1, 0.129032, 0.12> diffuse 1 phong 0.15 phong_size 20 }
}

// floor: plane { point = [0, 0, 0], normal = [0, 1, 0] }
plane { y, 0 texture { Floor } }

// mirror sphere: center = [-1.7, 1.0, -0.4], radius = 1.0
sphere { <-1.7, 1.0, 0.4>, 1.0 texture { Mirror } }

// glass sphere: center = [0.55, 0.75, 1.9], radius = 0.75
sphere { <0.55, 0.75, -1.9>, 0.75 material { Glass } }

// cylinder: base = [2.5, 0.0, -0.8], top = [2.5, 1.7, -0.8], radius = 0.6 (closed)
cylinder { <2.5, 0.0, 0.8>, <2.5, 1.7, 0.8>, 0.6 texture { Blue } }

// cone: base = [0.6, 0.0, -2.2], apex = [0.6, 2.4, -2.2], radius = 0.9 (closed base)
cone { <0.6, 0.0, 2.2>, 0.9, <0.6, 2.4, 2.2>, 0.0 texture { Gold } }

// cube: [-1, 1]³, scale 0.45, rotate_y 30°, translate [-2.6, 0.45, 2.3]
box {
  <-1, -1, -1>, <1, 1, 1>
  scale 0.45
  matrix < 0.866025404, 0, 0.5,   0, 1, 0,   -0.5, 0, 0.866025404,   0, 0, 0 >
  translate <-2.6, 0.45, -2.3>
  texture { Green }
}

// octahedron: |x| + |y| + |z| ≤ 1, scale 0.6, rotate_y 20°, translate [2.2, 0.6, 1.8]
intersection {
  plane { < 1,  1,  1>, 0.577350269 }
  plane { < 1,  1, -1>, 0.577350269 }
  plane { < 1, -1,  1>, 0.577350269 }
  plane { < 1, -1, -1>, 0.577350269 }
  plane { <-1,  1,  1>, 0.577350269 }
  plane { <-1,  1, -1>, 0.577350269 }
  plane { <-1, -1,  1>, 0.577350269 }
  plane { <-1, -1, -1>, 0.577350269 }
  scale 0.6
  matrix < 0.939692621, 0, 0.342020143,   0, 1, 0,   -0.342020143, 0, 0.939692621,   0, 0, 0 >
  translate <2.2, 0.6, -1.8>
  texture { Gold }
}
