vs.1.1
dcl_position v0
dcl_texcoord v3
mov oPos, v0 // output the vertex position in screen space
// Create neighbor-sampling texture coordinates by
// offsetting a single input texture coordinate according
// to several constants.

add oT0, v3, c0
add oT1, v3, c1
add oT2, v3, c2
add oT3, v3, c3
