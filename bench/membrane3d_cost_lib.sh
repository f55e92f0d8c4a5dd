# Shared by bench/membrane3d_cost.sh and bench/membrane3d_cuboid_cost.sh (sourced):
# one timed run of liggghts-membrane and the figures read from its screen output.
# The input prints "BENCH contacts per sphere N" after the timed run and, with a
# membrane, "BENCH detections N in M steps" (see in.membrane3d_cost).

bench_exe=$(readlink -f "$(dirname "${BASH_SOURCE[0]}")/../build/app/liggghts-membrane")

# The machine's busy CPU time so far, in clock ticks (user, nice, system, irq, softirq
# and steal of /proc/stat's cpu line), and its total: "BUSY TOTAL".
bench_cpu_ticks() {
  awk '/^cpu / { b = $2 + $3 + $4 + $7 + $8 + $9; print b, b + $5 + $6; exit }' /proc/stat
}

# Wait until for 3 s in a row no liggghts-membrane, mpirun or compiler runs and the
# machine is at least 90 % idle (another bench's runs follow each other within
# milliseconds): a step time measured beside another run is meaningless on this
# 2-core machine (BENCH_NO_WAIT=1: do not wait).
bench_busy='liggghts-membra|mpirun|mpiexec|orterun|cc1plus|ctest'
bench_wait_idle() {
  [ "${BENCH_NO_WAIT:-0}" = 1 ] && return 0
  local said= quiet=0 t0 t1
  while [ $quiet -lt 3 ]; do
    t0=$(bench_cpu_ticks); sleep 1; t1=$(bench_cpu_ticks)
    if pgrep -x "$bench_busy" > /dev/null 2>&1 ||
       ! awk -v a="$t0" -v b="$t1" 'BEGIN { split(a, x, " "); split(b, y, " ");
                                         exit !((y[1] - x[1]) <= 0.1 * (y[2] - x[2])) }'; then
      [ -n "$said" ] || { echo "[$(date +%T)] waiting for an idle machine:" \
        "$(pgrep -x -l "$bench_busy" | tr '\n' ' ')$(top -b -n 1 | sed -n 8p)" >&2; said=1; }
      quiet=0; sleep 4
    else
      quiet=$((quiet + 1))
    fi
  done
}

# bench_run NP INPUT [ARGS...]: wait for an idle machine, run INPUT on NP ranks (no log
# file); its screen output is left in $bench_log, its errors shown (on stderr). When
# other processes took more than 5 % of the machine's CPU time during it (its time is
# then suspect), it is run again, up to 3 times ($bench_others: their share of the last).
bench_run() {
  local np=$1 input=$2 try t0 t1 rusage; shift 2
  rusage=$(mktemp)
  for try in 1 2 3; do
    bench_wait_idle
    t0=$(bench_cpu_ticks)
    bench_log=$(/usr/bin/time -f "%e %U %S" -o "$rusage" mpirun --allow-run-as-root --oversubscribe \
      -np "$np" "$bench_exe" -in "$input" -log none "$@") || true
    t1=$(bench_cpu_ticks)
    grep "^ERROR" <<<"$bench_log" >&2 || true
    # the others' CPU time: the machine's busy time less this run's (mpirun and its ranks)
    bench_others=$(awk -v a="$t0" -v b="$t1" -v hz="$(getconf CLK_TCK)" -v n="$(nproc)" '
      { wall = $1; own = $2 + $3 }
      END { split(a, x, " "); split(b, y, " "); o = (y[1] - x[1]) / hz - own;
            printf "%.3f", (o > 0 ? o : 0) / (wall * n) }' "$rusage")
    [ "${BENCH_NO_WAIT:-0}" = 1 ] || awk -v o="$bench_others" 'BEGIN { exit !(o > 0.05) }' || break
    echo "[$(date +%T)] other processes took $bench_others of the CPU time during this run: again" >&2
  done
  rm -f "$rusage"
}

# bench_figures NSTEPS: of the last bench_run's timed run (its last loop),
# "ms_per_step,pair_ms_per_step,neigh_ms_per_step,contacts,detections"
bench_figures() {
  printf "%s,%s,%s,%s,%s" "$(grep "^Loop time" <<<"$bench_log" | tail -1 | awk '{printf "%.4f", 1000 * $4 / $9}')" \
    "$(grep "^Pair  time" <<<"$bench_log" | tail -1 | awk -v n="$1" '{printf "%.4f", 1000 * $5 / n}')" \
    "$(grep "^Neigh time" <<<"$bench_log" | tail -1 | awk -v n="$1" '{printf "%.4f", 1000 * $5 / n}')" \
    "$(grep "^BENCH contacts" <<<"$bench_log" | awk '{printf "%.3f", $5}')" \
    "$(grep "^BENCH detections" <<<"$bench_log" | awk '{print $3}')"
}
