#!/usr/bin/env bash
# Runs every libFuzzer target in BIN_DIR (default build/asan/bin) for SECONDS
# each (default 20), starting from its seed corpus fuzz/corpus/<reader>/
# (inputs made for fuzzing) and the reader's test data in tests/data/fe/.
# New corpus entries go to a scratch directory, so the repository stays as
# it is. Exits non-zero on the first crash, leak or sanitizer report; the
# reproducer is left in build/asan/fuzz-artifacts/.
set -euo pipefail
cd "$(dirname "$0")/.."
bin_dir=${1:-build/asan/bin}
seconds=${2:-20}
artifacts=build/asan/fuzz-artifacts
mkdir -p "$artifacts"
shopt -s nullglob
targets=("$bin_dir"/*_fuzz)
if [ ${#targets[@]} -eq 0 ]; then
  echo "run-fuzz: no fuzz targets in $bin_dir" >&2
  exit 1
fi
for t in "${targets[@]}"; do
  name=$(basename "$t" _fuzz)
  scratch=$(mktemp -d)
  seeds=()
  if [ -d "fuzz/corpus/$name" ]; then seeds=("fuzz/corpus/$name"); fi
  case "$name" in
    harwell_boeing) data=hb ;;
    matrix_market) data=mtx ;;
    matrix_files) data=calculix ;;
    *) data=$name ;;
  esac
  if [ -d "tests/data/fe/$data" ]; then seeds+=("tests/data/fe/$data"); fi
  echo "run-fuzz: $name for ${seconds} s"
  set +e
  "$t" "$scratch" "${seeds[@]}" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=4096 \
    -artifact_prefix="$artifacts/${name}-" -print_final_stats=1 > "$artifacts/$name.log" 2>&1
  rc=$?
  set -e
  tail -n 12 "$artifacts/$name.log"
  rm -rf "$scratch"
  if [ "$rc" -ne 0 ]; then
    echo "run-fuzz: $name FAILED (exit $rc); reproducer in $artifacts" >&2
    exit "$rc"
  fi
done
echo "run-fuzz: ${#targets[@]} targets clean"
