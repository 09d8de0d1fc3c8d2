vs_2_x
rep i0
break_ne r0.x, r1.x
endrep
setp_gt p0, r0, r1
(!p0) add r2, r2, r3
if p0.x
else
endif
