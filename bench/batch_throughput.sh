#!/bin/sh
# Throughput of `implicitfit batch` (issue 7): COUNT generated sphere clouds of POINTS oriented
# points each (noise 0.2% of the radius, 5% outliers), fitted
#   1. by a shell loop calling `implicitfit fit` once per file (the baseline a user would write),
#   2. by `implicitfit batch --jobs 1` and `--jobs 2`,
#   3. by `mpirun -np 2 implicitfit batch` when the CLI was built with MPI and mpirun exists.
# Prints inputs/s and points/s for each. Usage:
#   bench/batch_throughput.sh path/to/implicitfit [COUNT=200] [POINTS=2000] [WORKDIR]
set -eu
cli=${1:?usage: $0 path/to/implicitfit [count] [points] [workdir]}
count=${2:-200}
points=${3:-2000}
work=${4:-$(mktemp -d /tmp/implicitfit_batch_bench.XXXXXX)}
mkdir -p "$work/clouds"

echo "generating $count clouds of $points points in $work/clouds"
i=0
while [ "$i" -lt "$count" ]; do
  name=$(printf 'cloud_%04d' "$i")
  if [ ! -f "$work/clouds/$name.xyz" ]; then
    r=$(awk -v i="$i" 'BEGIN { printf "%.3f", 0.5 + (i % 10) * 0.15 }')
    printf '{"format": "implicitfit-model", "version": 1, "root": {"type": "sphere", "center": [%d, 0.5, -1], "radius": %s}}\n' \
      "$((i % 13))" "$r" > "$work/truth.json"
    noise=$(awk -v r="$r" 'BEGIN { printf "%.6f", 0.002 * r }')
    "$cli" sample "$work/truth.json" --count "$points" --noise "$noise" --outliers 0.05 --seed "$((i + 1))" \
      --out "$work/clouds/$name.xyz"
  fi
  i=$((i + 1))
done
total_points=$((count * points))

now() { date +%s.%N; }
report() {  # label start end
  awk -v l="$1" -v s="$2" -v e="$3" -v n="$count" -v p="$total_points" \
    'BEGIN { t = e - s; printf "%-28s %8.2f s %9.1f inputs/s %11.0f points/s\n", l, t, n / t, p / t }'
}

rm -rf "$work/loop" && mkdir -p "$work/loop"
start=$(now)
for f in "$work"/clouds/*.xyz; do
  b=$(basename "$f" .xyz)
  "$cli" fit "$f" --model sphere --out "$work/loop/$b.model.json" --report "$work/loop/$b.report.json" > /dev/null
done
end=$(now)
loop_line=$(report "shell loop of fit" "$start" "$end")

lines=""
for jobs in 1 2; do
  rm -rf "$work/batch$jobs"
  start=$(now)
  "$cli" batch "$work/clouds" --model sphere --out-dir "$work/batch$jobs" --jobs "$jobs" > /dev/null 2>&1 || true
  end=$(now)
  lines="$lines$(report "batch --jobs $jobs" "$start" "$end")
"
done

mpi_line=""
if command -v mpirun > /dev/null 2>&1 && "$cli" batch --help 2>/dev/null | grep -q "MPI"; then
  rm -rf "$work/mpi2"
  start=$(now)
  # (Open MPI refuses to run as root unless these are set; harmless otherwise.)
  OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 mpirun --oversubscribe -np 2 "$cli" batch "$work/clouds" --model sphere --out-dir "$work/mpi2" --jobs 1 \
    > /dev/null 2>&1 || true
  end=$(now)
  mpi_line=$(report "mpirun -np 2 batch --jobs 1" "$start" "$end")
fi

echo "$count inputs, $points points each, $(nproc) cores"
echo "$loop_line"
printf '%s' "$lines"
[ -n "$mpi_line" ] && echo "$mpi_line"
ok=$(grep -c ',ok,' "$work/batch2/summary.csv" || true)
echo "batch --jobs 2: $ok of $count inputs ok"
