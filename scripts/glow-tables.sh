#!/usr/bin/env bash
# The glow table of every scene in listings/scenes, for checking that a refactor changed no
# figure: run it with the old and the new binary, then compare the two folders.
#   scripts/glow-tables.sh OLD/tierlift /tmp/before
#   scripts/glow-tables.sh build/cli/tierlift /tmp/after
#   scripts/glow-tables.sh --compare /tmp/before /tmp/after
# Timings ("in 12.3 ms") are masked in the comparison; every other character must match.
set -euo pipefail
cd "$(dirname "$0")/.."
if [ "${1:-}" = "--compare" ]; then
  mask() { sed -E 's/[0-9]+(\.[0-9]+)? (ms|s)\b/<t> \2/g' "$1"; }
  rc=0
  for f in "$2"/*.txt; do
    n=$(basename "$f")
    if ! diff <(mask "$f") <(mask "$3/$n"); then
      echo "glow-tables: $n differs" >&2
      rc=1
    fi
  done
  echo "glow-tables: compared $(find "$2" -name '*.txt' | wc -l) tables"
  exit "$rc"
fi
tierlift=$1 out=$2
mkdir -p "$out"
for scene in listings/scenes/*.json; do
  case $scene in *schema*) continue ;; esac
  name=$(basename "$scene" .json)
  status=0
  "$tierlift" glow --scene "$scene" --backend all -q >"$out/$name.txt" 2>&1 || status=$?
  echo "exit $status" >>"$out/$name.txt"
done
