vs.1.1
// tierlift radial beams, Direct3D 8 tier: the star's vertex listing (as star4.vsh): four
// texture-coordinate sets, the quad uv plus the time-dependent offsets c0..c3.
dcl_position v0
dcl_texcoord v3

mov oPos, v0 // the position is already in clip space

add oT0, v3, c0
add oT1, v3, c1
add oT2, v3, c2
add oT3, v3, c3
