; Seed for fuzz_parser: a vs_3_0 listing in the shape fxc writes.
vs_3_0
def c8, 1, 0, 0.5, 2
defi i0, 4, 0, 1, 0
dcl_position v0
dcl_normal v1
dcl_texcoord v2
dcl_position o0
dcl_texcoord o1.xy
dcl_color o2
dcl_texcoord1 o3
dcl_2d s0
dp4 o0.x, v0, c0
dp4 o0.y, v0, c1
dp4 o0.z, v0, c2
dp4 o0.w, v0, c3
mov o1.xy, v2
mov r1, c8.y
loop aL, i0
  add r1, r1, c[aL + 20]
endloop
texldl r2, v2, s0
setp_ge p0, v1, c8.y
(p0) mul r1, r1, c8.w
(!p0.x) mov r1.x, c8.x
sincos r3.xy, v1.x
add_sat o2, r1, r2
mov o3, r3.xyxy
