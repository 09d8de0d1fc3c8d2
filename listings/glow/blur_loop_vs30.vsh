vs_3_0
// Tier dx9c's blur vertex listing: the quad's position and uv, handed to the pixel
// listing by semantic (texcoord0). The tap offsets are added per tap in the pixel listing.
dcl_position v0
dcl_texcoord0 v1
dcl_position o0
dcl_texcoord0 o1
mov o0, v0
mov o1, v1
