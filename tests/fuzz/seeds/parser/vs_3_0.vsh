vs_3_0
dcl_position v0
dcl_texcoord0 v1
dcl_position o0
dcl_texcoord12 o11
dcl_2d s0
texldl r0, v1, s0
loop aL, i0
mov o[aL + 1], r0
endloop
mova_sat a0.x, r1
mov r2, r1_abs
sincos r3.xy, r1.x
mov o0, v0
