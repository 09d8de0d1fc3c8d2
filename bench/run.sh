#!/usr/bin/env bash
# Runs every benchmark program (of the build given, by default the RelWithDebInfo one of
# `cmake --preset default`) and prints our figures beside the peer's
# measured in the same run, as ratios.
# Usage: bench/run.sh [build-dir]   (default: build, configured by `cmake --preset default`)
# TIERLIFT_BENCH_FILTER=REGEX runs only the benchmarks it matches (e.g. 'Glow').
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
benches=(bench_front_end bench_codegen)
for extra in bench_interpreter bench_vulkan bench_glow bench_corpus; do
  if grep -q "$extra" "$build/build.ninja" 2>/dev/null; then benches+=("$extra"); fi
done
cmake --build "$build" --target "${benches[@]}" >/dev/null
tmp=$(mktemp -d)
filter=${TIERLIFT_BENCH_FILTER:-.}
for b in "${benches[@]}"; do
  # A program with nothing the filter matches is left out (it would print no JSON).
  "$build/bench/$b" --benchmark_list_tests --benchmark_filter="$filter" | grep -q . || continue
  "$build/bench/$b" --benchmark_format=json --benchmark_min_time=0.5 \
    --benchmark_filter="$filter" >"$tmp/$b.json"
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
def find(base):
    # A row by its function (and BENCHMARK_CAPTURE) name: Google Benchmark appends
    # "/real_time", "/iterations:N", "/min_time:…" to the name it reports.
    return next((b for n, b in rows.items() if n == base or n.startswith(base + "/")), None)
print(f"{'benchmark':56} {'time':>12} {'MB/s':>9} {'items/s':>12}")
for name, b in rows.items():
    mbs = b.get("bytes_per_second", 0) / 1e6
    print(f"{name:56} {sec(b)*1e6:10.1f}us {mbs:9.2f} {b.get('items_per_second', 0):12.0f}")
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
    o, p = find(ours), find(peer)
    if o and p:
        if what == "time":
            r = sec(p) / sec(o)
            print(f"speed-up {ours} vs {peer}: {r:.2f}x (peer time / our time)")
        else:
            r = o["bytes_per_second"] / p["bytes_per_second"]
            print(f"throughput ratio {ours} / {peer}: {r:.2f}")
# The glow (bench_glow): frames at 1920x1080, downsample 4, measured in this run. Lines
# marked "target" state what the issue asks: Vulkan / hand-written GLSL <= 1.0,
# interpreter / OpenCV <= 2.0.
glow_cases = ("dx9_rgba32f", "dx9_rgba8", "dx8_rgba8")
# (benchmark, ours, peer, their names in the line, target): pairs measured frame for frame.
glow_pairs = (("BM_Glow_VulkanVsGlsl", "vulkan", "glsl", "Vulkan", "hand-written GLSL", 1.0),
              ("BM_Glow_InterpreterVsOpenCV", "interpreter", "opencv", "interpreter", "OpenCV", 2.0))
for bench, ours, peer, ours_text, peer_text, target in glow_pairs:
    for case in glow_cases:
        pair = find(f"{bench}/{case}")
        if pair and f"{ours}_over_{peer}" in pair:
            print(f"glow 1080p/4 {case}: {ours_text} frame / {peer_text} frame = "
                  f"{pair[f'{ours}_over_{peer}']:.2f} ({pair[f'{ours}_ms']:.1f} ms vs "
                  f"{pair[f'{peer}_ms']:.1f} ms, medians, alternating; target <= {target})")
glow_peer = find("BM_Glow_OpenCV")
if glow_peer:
    for case in glow_cases:
        for what, bench in (("Vulkan", "BM_Glow_Vulkan"), ("interpreter", "BM_Glow_Interpreter")):
            ours = find(f"{bench}/{case}")
            if ours:
                print(f"glow 1080p/4 {case}: {what} frame / OpenCV frame = "
                      f"{sec(ours)/sec(glow_peer):.2f} ({sec(ours)*1e3:.1f} ms vs "
                      f"{sec(glow_peer)*1e3:.1f} ms, each measured on its own)")
# The interpreter before and after its vectorisation, when the program has both rows
# (BM_Glow_InterpreterOld/<case>: the old path, kept for this ratio).
for case in glow_cases:
    old, new = find(f"BM_Glow_InterpreterOld/{case}"), find(f"BM_Glow_Interpreter/{case}")
    if old and new:
        print(f"glow 1080p/4 {case}: interpreter speed-up new over old = "
              f"{sec(old)/sec(new):.1f}x ({sec(old)*1e3:.0f} ms -> {sec(new)*1e3:.0f} ms)")
# tierlift test (bench_corpus): cases per second with 1 and 2 workers, measured alternately
# in the same benchmark after a warm-up (target: two workers >= 1.8x one), and the full lift
# per case against the floors measured in the same run on the same SPIR-V (target <= 1.5).
for bench, corpus in (("CheckOnly", "our corpus"), ("CheckOnlyGenerated", "2,000 generated ps_2_0"),
                      ("FullLift", "our corpus"), ("FullLiftGenerated", "2,000 generated ps_2_0")):
    w = find(f"BM_Corpus_Workers/{bench}")
    if not w or "two_over_one" not in w:
        continue
    print(f"tierlift test {bench}, {corpus}: 1 worker {w['one_cases_per_s']:.1f} cases/s, "
          f"2 workers {w['two_cases_per_s']:.1f} cases/s, 2 workers / 1 worker = "
          f"{w['two_over_one']:.2f}x (target >= 1.8); CPU per case {w['one_cpu_ms_per_case']:.3f} / "
          f"{w['two_cpu_ms_per_case']:.3f} ms, of which the coordinator "
          f"{w['one_coordinator_cpu_ms_per_case']:.3f} / {w['two_coordinator_cpu_ms_per_case']:.3f} ms")
# Floor 1: lavapipe's vkCreateGraphicsPipelines for the case's pipelines. Floor 2: that plus
# each pipeline's first draws of one pixel, where llvmpipe compiles the shaders to machine
# code (in vkCreateGraphicsPipelines lavapipe only translates SPIR-V to its own IR).
for bench, corpus in (("FullLift", "our corpus"), ("FullLiftGenerated", "200 generated ps_2_0")):
    lift = find(f"BM_Corpus_InProcess/{bench}")
    if not lift or lift.get("floor_ms_per_case", 0) <= 0:
        continue
    per_case, cpu_case = lift["lift_ms_per_case"], lift["lift_cpu_ms_per_case"]
    f1, f2 = lift["floor_ms_per_case"], lift["floor2_ms_per_case"]
    print(f"tierlift test full lift in process, {corpus}: {per_case:.2f} ms/case; "
          f"floor 1 (vkCreateGraphicsPipelines, {lift['pipelines_per_case']:.2f} pipelines a case) "
          f"{f1:.2f} ms, ratio {per_case / f1:.2f}; floor 2 (pipelines + first draws of one pixel) "
          f"{f2:.2f} ms, ratio {per_case / f2:.2f} (target <= 1.5)")
    # CPU time of the whole process (lavapipe's queue thread included, where llvmpipe compiles
    # at the first draw): the ratios a busy machine changes least.
    c1, c2 = lift["floor_cpu_ms_per_case"], lift["floor2_cpu_ms_per_case"]
    print(f"tierlift test full lift in process, {corpus}, CPU time: {cpu_case:.2f} ms/case; "
          f"floor 1 {c1:.2f} ms, ratio {cpu_case / c1:.2f}; floor 2 {c2:.2f} ms "
          f"(of which the draws {lift['floor2_draw_cpu_ms_per_case']:.2f}), ratio "
          f"{cpu_case / c2:.2f} (target <= 1.5)")
lift = find("BM_Corpus_InProcess/FullLift")
if lift and lift.get("floor_ms_per_case", 0) > 0:
    per_case = lift["lift_ms_per_case"]
    per_set = find("BM_Corpus_InProcess/FullLiftPipelinePerSet")
    if per_set:
        old = per_set["lift_ms_per_case"]
        print(f"tierlift test full lift, a pipeline per input set instead: {old:.1f} ms/case "
              f"({per_set['pipelines_per_case']:.2f} pipelines a case), "
              f"{old / per_case:.2f}x the time of one per case")
# Scaling: BM_GlowScale_<device>/<w>x<h>/taps:<n>. The exponent b of time = a * (pixels *
# taps)^b, least squares in log-log over every size and tap count of the device (1.0: linear).
import math, re
scale = {}
for name, b in rows.items():
    m = re.match(r"BM_GlowScale_([^/]+)/(\d+)x(\d+)/taps:(\d+)", name)
    if m:
        w, h, taps = int(m.group(2)), int(m.group(3)), int(m.group(4))
        scale.setdefault(m.group(1), []).append((w, h, taps, sec(b)))
for device, pts in sorted(scale.items()):
    print(f"scaling {device}:")
    for w, h, taps, t in sorted(pts):
        print(f"  {w}x{h} taps {taps:2d}: {t*1e3:9.2f} ms")
    if len(pts) >= 2:
        xs = [math.log(w * h * taps) for w, h, taps, _ in pts]
        ys = [math.log(t) for *_, t in pts]
        mx, my = sum(xs) / len(xs), sum(ys) / len(ys)
        sxx = sum((x - mx) ** 2 for x in xs)
        if sxx > 0:
            b = sum((x - mx) * (y - my) for x, y in zip(xs, ys)) / sxx
            print(f"  exponent of time against pixels x taps: {b:.2f} (1.0: linear)")
PY
rm -rf "$tmp"

# ---- the CPU device (bench_cpu_glow): block executor against the per-pixel VM it replaced and
# against OpenCV, glow at 480x270, 1920x1080, 3840x2160 (downsample 4), 13 and 25 taps ----------
if grep -q bench_cpu_glow "$build/build.ninja" 2>/dev/null; then
  cmake --build "$build" --target bench_cpu_glow >/dev/null
fi
# TIERLIFT_BENCH_FILTER applies here too (e.g. 'Corpus' runs none of these).
if grep -q bench_cpu_glow "$build/build.ninja" 2>/dev/null &&
  "$build/bench/bench_cpu_glow" --benchmark_list_tests --benchmark_filter="$filter" | grep -q .; then
  cpu_json=$(mktemp)
  "$build/bench/bench_cpu_glow" --benchmark_format=json --benchmark_min_time=1 \
    --benchmark_filter="$filter" >"$cpu_json"
  python3 - "$cpu_json" <<'PY'
import json, math, sys
rows = {b["name"]: b for b in json.load(open(sys.argv[1]))["benchmarks"] if "error_occurred" not in b}
def get(prefix):
    return next((b for n, b in rows.items() if n == prefix or n.startswith(prefix + "/")), None)
def ms(b, key="real_time"):
    return b[key] * {"ns": 1e-6, "us": 1e-3, "ms": 1.0, "s": 1e3}[b.get("time_unit", "ns")]
sizes = {0: "480x270", 1: "1920x1080", 2: "3840x2160"}
print("\nCPU device glow (dx9, RGBA32F, downsample 4), wall clock, all cores:")
print(f"{'size':>10} {'taps':>4} {'block ms':>9} {'OpenCV ms':>10} {'block/OpenCV':>13}")
fit = []
for s, name in sizes.items():
    for taps in (13, 25):
        b, o = get(f"BM_CpuGlow_Block/size:{s}/taps:{taps}"), get(f"BM_CpuGlow_OpenCV/size:{s}/taps:{taps}")
        if b and o:
            print(f"{name:>10} {taps:>4} {ms(b):9.1f} {ms(o):10.2f} {ms(b)/ms(o):12.1f}x")
            fit.append((math.log(b["pixels"] * taps), math.log(ms(b))))
if len(fit) >= 2:
    mx = sum(x for x, _ in fit) / len(fit); my = sum(y for _, y in fit) / len(fit)
    k = sum((x - mx) * (y - my) for x, y in fit) / sum((x - mx) ** 2 for x, _ in fit)
    print(f"time ~ (pixels x taps)^{k:.2f} (least squares over the block rows)")
old, new = get("BM_CpuGlow_Scalar/size:1/taps:13"), get("BM_CpuGlow_Block/size:1/taps:13")
if old and new:
    print(f"block vs per-pixel VM, 1080p 13 taps, all cores: {ms(old)/ms(new):.1f}x faster")
o1, b1, s1 = (get(f"BM_CpuGlow_OneThread_{k}") for k in ("OpenCV", "Block", "Scalar"))
if o1 and b1 and s1:
    print(f"one thread, CPU time (1080p, 13 taps): block {ms(b1, 'cpu_time'):.1f} ms, per-pixel VM "
          f"{ms(s1, 'cpu_time'):.1f} ms ({ms(s1, 'cpu_time')/ms(b1, 'cpu_time'):.1f}x), OpenCV "
          f"{ms(o1, 'cpu_time'):.1f} ms (block/OpenCV {ms(b1, 'cpu_time')/ms(o1, 'cpu_time'):.1f}x)")
for tier in ("dx9_rgba8", "dx8_rgba8"):
    b, s = get(f"BM_CpuGlow_Tier/block_{tier}"), get(f"BM_CpuGlow_Tier/scalar_{tier}")
    if b and s:
        print(f"{tier} 1080p: block {ms(b):.0f} ms, per-pixel VM {ms(s):.0f} ms ({ms(s)/ms(b):.1f}x)")
PY
  rm -f "$cpu_json"
fi
