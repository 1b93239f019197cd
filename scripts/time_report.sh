#!/usr/bin/env bash
# Times a full `rolling-disk report` (HTML, LaTeX with its PNGs, JSON) with the release binary
# already built, against `rolling-disk check` alone, both in the same run: N runs of each,
# interleaved, then the median of each. With a second binary (OLD, e.g. a build of an earlier
# commit) its report is timed in the same interleaved runs, so that the two are compared under
# the same load. The machine's load is printed first: with other work running, wall times grow.
#
# Usage: scripts/time_report.sh [N] [OLD]   (default N 5; needs `cargo build --release` first)
set -euo pipefail
n=${1:-5}
old=${2:-}
here=$(cd "$(dirname "$0")/.." && pwd)
bin=${CARGO_TARGET_DIR:-$here/target}/release/rolling-disk
[ -x "$bin" ] || { echo "time_report.sh: $bin is missing; run cargo build --release first" >&2; exit 1; }
[ -z "$old" ] || [ -x "$old" ] || { echo "time_report.sh: $old is not an executable" >&2; exit 1; }
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
echo "load average: $(cut -d' ' -f1-3 /proc/loadavg); cores: $(nproc)"
wall() { local s e; s=$(date +%s.%N); "$@" >/dev/null 2>&1; e=$(date +%s.%N); echo "$e - $s" | bc; }
report=(); check=(); before=()
for _ in $(seq "$n"); do
  report+=("$(wall "$bin" report --out "$out/r")")
  check+=("$(wall "$bin" check)")
  [ -z "$old" ] || before+=("$(wall "$old" report --out "$out/o")")
done
median() { printf '%s\n' "$@" | sort -g | awk '{a[NR]=$1} END {print (NR%2 ? a[(NR+1)/2] : (a[NR/2]+a[NR/2+1])/2)}'; }
echo "report (all formats), $n runs: ${report[*]} s; median $(median "${report[@]}") s"
echo "check alone,          $n runs: ${check[*]} s; median $(median "${check[@]}") s"
if [ -n "$old" ]; then
  echo "report with $old, $n runs: ${before[*]} s; median $(median "${before[@]}") s"
  echo "ratio of medians (old / this): $(echo "scale=2; $(median "${before[@]}") / $(median "${report[@]}")" | bc)"
fi
