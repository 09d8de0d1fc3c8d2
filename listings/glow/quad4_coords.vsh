vs.2.0
// tierlift helper (glow): full-screen quad with four texture coordinates made from one
// quad uv, each with its own scale and offset: oTk = v3 * c(k+4) + ck.
// The scale lets a pass read a texture whose size is not an exact multiple of the
// target's (downsampling, upsampling); the offset carries the sample position, half
// texel included (the article's rule for Direct3D), and is set on the CPU.
dcl_position v0
dcl_texcoord v3

mov oPos, v0 // the position is already in clip space

mad oT0, v3, c4, c0
mad oT1, v3, c5, c1
mad oT2, v3, c6, c2
mad oT3, v3, c7, c3
