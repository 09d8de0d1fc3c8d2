vs.2.0
// tierlift radial beams (Meshuggah "Beams"): the star. Four texture-coordinate sets made
// from the quad's one uv, each moved by its own offset c0..c3, a function of time that the
// application evaluates every frame (so the four move differently and the surface churns).
dcl_position v0
dcl_texcoord v3

mov oPos, v0 // the position is already in clip space

add oT0, v3, c0
add oT1, v3, c1
add oT2, v3, c2
add oT3, v3, c3
