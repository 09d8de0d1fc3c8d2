vs_1_1
#define BASE c[a0.x + 4]
dcl_position v0
mov a0.x, v0.x
mov oPos, BASE
mov oT3.xy, v0
