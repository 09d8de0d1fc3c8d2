vs.1.1
// tierlift radial beams, Direct3D 8 tier: four zoomed copies a pass (ps.1.x reads four
// textures). oTk = uv · c(k+4) + ck; a vs.1.1 instruction reads one constant register, so
// each coordinate is a mul by its scale and an add of its offset.
dcl_position v0
dcl_texcoord v3

mov oPos, v0 // the position is already in clip space

mul r0, v3, c4
add oT0, r0, c0
mul r1, v3, c5
add oT1, r1, c1
mul r2, v3, c6
add oT2, r2, c2
mul r3, v3, c7
add oT3, r3, c3
