#!/usr/bin/env bash
# Runs every benchmark program (Release build) and prints our figures beside the peer's
# measured in the same run, as ratios.
# Usage: bench/run.sh [build-dir]   (default: build, configured by `cmake --preset default`)
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
benches=(bench_front_end bench_codegen)
for extra in bench_interpreter bench_vulkan; do
  if grep -q "$extra" "$build/build.ninja" 2>/dev/null; then benches+=("$extra"); fi
done
cmake --build "$build" --target "${benches[@]}" >/dev/null
tmp=$(mktemp -d)
for b in "${benches[@]}"; do
  "$build/bench/$b" --benchmark_format=json --benchmark_min_time=0.5 >"$tmp/$b.json"
done
python3 - "$tmp" <<'PY'
import json, os, sys
rows = {}
for f in sorted(os.listdir(sys.argv[1])):
    for b in json.load(open(os.path.join(sys.argv[1], f)))["benchmarks"]:
        if "error_occurred" not in b:
            rows[b["name"]] = b
def sec(b):
    scale = {"ns": 1e-9, "us": 1e-6, "ms": 1e-3, "s": 1.0}[b.get("time_unit", "ns")]
    return b["real_time"] * scale
print(f"{'benchmark':44} {'time':>12} {'MB/s':>9} {'items/s':>12}")
for name, b in rows.items():
    mbs = b.get("bytes_per_second", 0) / 1e6
    print(f"{name:44} {sec(b)*1e6:10.1f}us {mbs:9.2f} {b.get('items_per_second', 0):12.0f}")
print()
# (ours, peer, what): ratio > 1 means ours is faster.
pairs = [
    ("BM_ParseValidate", "BM_Peer_SpirvToolsAssemble", "bytes/s"),
    ("BM_ParseValidateAssemble", "BM_Peer_SpirvToolsAssemble", "bytes/s"),
    ("BM_Translate_Listing1", "BM_Peer_Glslang_Vertex8", "time"),
    ("BM_Translate_Listing2", "BM_Peer_Glslang_Fragment8", "time"),
    ("BM_Interpreter_Listing2_OneCore", "BM_Peer_PlainLoop", "time"),
    ("BM_Interpreter_Listing2_AllCores", "BM_Peer_PlainLoop", "time"),
    ("BM_Vulkan_Listing2", "BM_Vulkan_PeerInterpreter_Listing2_AllCores", "time"),
]
for ours, peer, what in pairs:
    if ours in rows and peer in rows:
        if what == "time":
            r = sec(rows[peer]) / sec(rows[ours])
            print(f"speed-up {ours} vs {peer}: {r:.2f}x (peer time / our time)")
        else:
            r = rows[ours]["bytes_per_second"] / rows[peer]["bytes_per_second"]
            print(f"throughput ratio {ours} / {peer}: {r:.2f}")
PY
rm -rf "$tmp"
