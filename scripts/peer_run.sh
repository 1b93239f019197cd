#!/usr/bin/env bash
# Builds M. Batista's Euler disk program (the working copy TheLlamamarketer/Eulers-Disk-Simulation)
# from a fetched bare git snapshot in a temporary directory, outside this project, and runs it
# on a response file (from `rolling-disk peer export SCENE`). Nothing of the peer enters the
# project: only its result.txt and report.txt are copied to OUT_DIR, with a provenance note.
#
# usage: scripts/peer_run.sh RESPONSE_FILE OUT_DIR [PEER_GIT_DIR]
#   PEER_GIT_DIR defaults to /work/.mirror/TheLlamamarketer+Eulers-Disk-Simulation/repo
#   PEER_KEEP_ROWS=N (optional) stores result.txt subsampled to about N evenly spaced rows plus the
#   last row and the two rows around every change of mode, with runs of spaces squeezed (the
#   columns stay whitespace-separated, as `rolling-disk peer compare` reads them).
#   PEER_SQUEEZE=1 (optional, without PEER_KEEP_ROWS) stores every row of result.txt as written, with
#   runs of spaces squeezed (the numbers and their digits untouched): a raw record, smaller.
#   PEER_SLIP_REGULARIZATION=EPS (optional) sets the peer's slip regularization speed (m/s, its
#   constant slip_regularization, 1e-3 in its source) in the temporary copy before building: an
#   experiment on the peer's modelling choice, recorded in provenance.txt.
# needs: git, gfortran
set -euo pipefail
response=${1:?usage: scripts/peer_run.sh RESPONSE_FILE OUT_DIR [PEER_GIT_DIR]}
out=${2:?usage: scripts/peer_run.sh RESPONSE_FILE OUT_DIR [PEER_GIT_DIR]}
repo=${3:-/work/.mirror/TheLlamamarketer+Eulers-Disk-Simulation/repo}
command -v gfortran >/dev/null || { echo "peer_run.sh: gfortran is not installed (apt-get install gfortran)" >&2; exit 1; }
[ -f "$response" ] || { echo "peer_run.sh: $response: no such response file (write one with rolling-disk peer export SCENE --out FILE)" >&2; exit 1; }
commit=$(git -C "$repo" rev-parse HEAD)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
src="$work/src"
mkdir -p "$src" "$work/build"
# Only the sources the headless program needs (the snapshot may lack large data files).
for p in screen model2 hairer zeroin.f; do
  git -C "$repo" archive HEAD "$p" | tar -x -C "$src"
done
changed="none"
if [ -n "${PEER_SLIP_REGULARIZATION:-}" ]; then
  f="$src/model2/disk_data.f90"
  grep -q 'slip_regularization = 1.0e-3_8' "$f" || { echo "peer_run.sh: the peer's slip_regularization constant is not where expected" >&2; exit 1; }
  sed -i "s/slip_regularization = 1.0e-3_8/slip_regularization = ${PEER_SLIP_REGULARIZATION}_8/" "$f"
  changed="slip_regularization set to ${PEER_SLIP_REGULARIZATION} m/s in model2/disk_data.f90 (source: 1.0e-3)"
fi
# The compile and link order of the peer's own run.bat; its flags (-w, no optimisation).
units="screen/mchr.f90 screen/mn2c.f90 screen/mio.f90 screen/mcalc.f90 screen/mui.f90
model2/disk_data.f90 model2/cdata.f90 model2/prop.f model2/disk0.f90 model2/disk.f90
model2/ztime.f90 model2/solout.f90 model2/post.f90 model2/input.f90 model2/integ.f90
model2/main.f90 zeroin.f hairer/hinit.for hairer/cdopri.for hairer/contd5.for
hairer/contd8.for hairer/dop853.for hairer/dopri5.for hairer/dopcor.for hairer/dp86co.for"
objs=()
for u in $units; do
  o="$work/build/$(basename "$u").o"
  gfortran -w -c "$src/$u" -J "$work/build" -I "$work/build" -o "$o"
  objs+=("$o")
done
gfortran -o "$work/build/edisk" "${objs[@]}"
# The peer reads its prompts' answers from standard input: comments and blank lines removed.
sed -e 's/#.*$//' -e 's/[[:space:]]*$//' -e '/^$/d' "$response" > "$work/input.txt"
run="$work/run"
mkdir -p "$run"
(cd "$run" && "$work/build/edisk" < "$work/input.txt" > "$work/stdout.txt" 2>&1) || {
  echo "peer_run.sh: the peer failed; its output:" >&2; cat "$work/stdout.txt" >&2; exit 1; }
mkdir -p "$out"
cp "$run/report.txt" "$out/"
rows=$(($(wc -l < "$run/result.txt") - 1))
if [ -n "${PEER_KEEP_ROWS:-}" ] && [ "$rows" -gt "$PEER_KEEP_ROWS" ]; then
  every=$(( (rows + PEER_KEEP_ROWS - 1) / PEER_KEEP_ROWS ))
  awk -v every="$every" -v last="$((rows + 1))" '
    NR == 1 { print; next }
    { line[NR] = $0; mode[NR] = $NF }
    END {
      for (i = 2; i <= last; i++) {
        keep = ((i - 2) % every == 0) || i == last || (i > 2 && mode[i] != mode[i-1]) || (i < last && mode[i] != mode[i+1])
        if (keep) { s = line[i]; gsub(/ +/, " ", s); sub(/^ /, "", s); print s }
      }
    }' "$run/result.txt" > "$out/result.txt"
  subsampled="result.txt: every ${every}th of $rows rows, the last, and the rows around each mode change; spaces squeezed"
elif [ -n "${PEER_SQUEEZE:-}" ]; then
  awk 'NR == 1 { print; next } { s = $0; gsub(/ +/, " ", s); sub(/^ /, "", s); print s }' "$run/result.txt" > "$out/result.txt"
  subsampled="result.txt: all $rows rows as written, spaces squeezed"
else
  cp "$run/result.txt" "$out/"
  subsampled="result.txt: all $rows rows as written"
fi
cp "$response" "$out/response.txt"
{
  echo "peer: M. Batista's Euler disk simulation, working copy github:TheLlamamarketer/Eulers-Disk-Simulation"
  echo "commit: $commit"
  echo "built: gfortran -w ($(gfortran --version | head -1)), DOP853 (high precision), by scripts/peer_run.sh"
  echo "response: response.txt (rolling-disk peer export)"
  echo "$subsampled"
  echo "peer source changed: $changed"
  echo "date: $(date -u +%Y-%m-%d)"
} > "$out/provenance.txt"
echo "peer run written to $out (result.txt $(wc -l < "$out/result.txt") lines)"
