vs.2.0
// tierlift radial beams: eight zoomed copies a pass. Copy k reads the light image at
// oTk = uv · c(k+8) + ck: the scale shrinks the quad's texture range toward the centre
// (1 − 2 · i · 0.0075 for copy i in the article), the offset keeps the centre fixed and
// carries the half texel.
dcl_position v0
dcl_texcoord v3

mov oPos, v0 // the position is already in clip space

mad oT0, v3, c8, c0
mad oT1, v3, c9, c1
mad oT2, v3, c10, c2
mad oT3, v3, c11, c3
mad oT4, v3, c12, c4
mad oT5, v3, c13, c5
mad oT6, v3, c14, c6
mad oT7, v3, c15, c7
