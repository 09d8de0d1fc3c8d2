vs.1.1
// tierlift helper (glow), Direct3D 8 tier: the vs.1.1 form of quad4_coords.vsh, with the
// same constants: oTk = v3 * c(k+4) + ck (offsets c0..c3, scales c4..c7).
// vs.1.1 lets an instruction read only one constant register, so the mad of the vs.2.0
// form becomes a mul by the scale and an add of the offset.
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
