#!/usr/bin/env bash
# Runs the benchmarks (Release build) and prints our throughput beside the peer's, as ratios.
# Usage: bench/run.sh [build-dir]   (default: build, configured by `cmake --preset default`)
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
cmake --build "$build" --target bench_front_end >/dev/null
out=$(mktemp)
"$build/bench/bench_front_end" --benchmark_format=json --benchmark_min_time=0.5 >"$out"
python3 - "$out" <<'PY'
import json, sys
data = json.load(open(sys.argv[1]))
rows = {b["name"]: b for b in data["benchmarks"] if "error_occurred" not in b}
def mbs(b): return b.get("bytes_per_second", 0) / 1e6
def ips(b): return b.get("items_per_second", 0)
print(f"{'benchmark':34} {'MB/s':>10} {'items/s':>12}")
for name, b in rows.items():
    print(f"{name:34} {mbs(b):10.2f} {ips(b):12.0f}")
peer = rows.get("BM_Peer_SpirvToolsAssemble")
if peer:
    for name in ("BM_ParseValidate", "BM_ParseValidateAssemble"):
        if name in rows:
            print(f"ratio {name} / SPIRV-Tools text assembler (MB/s): {mbs(rows[name]) / mbs(peer):.2f}")
PY
rm -f "$out"
