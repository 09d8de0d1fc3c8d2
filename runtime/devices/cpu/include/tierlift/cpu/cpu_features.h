// Which build of the CPU device's block loops runs on this machine. Each loop has a baseline
// build and an AVX2 (with FMA where it needs it) build of the same steps, which compute the
// same bits; the wider one runs when the CPU has it. TIERLIFT_CPU_BASELINE in the
// environment (any value but empty or "0") keeps every loop on its baseline build: the tests
// run the identity tests that way too, so both builds are checked on an AVX2 machine.
#pragma once

namespace tierlift::cpu {

bool cpu_runs_avx2();     // the block executor's steps
bool cpu_runs_avx2_fma(); // interpolation, texture reads, RGBA8 stores

} // namespace tierlift::cpu
