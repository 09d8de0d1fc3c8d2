; Seed for fuzz_parser: vs_2_x with predicates and break comparisons.
vs_2_x
defi i0, 4, 0, 1, 0
dcl_position v0
dcl_normal v1
mov r0, c0
rep i0
  add r0, r0, c1
  break_gt r0.x, c2.x
endrep
setp_le p0, v1, c3
(p0.y) mul r0, r0, v1
if p0.x
  mov r0.w, c4.x
endif
add oPos, v0, r0
