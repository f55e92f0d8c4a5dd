#!/bin/sh
# "BENCH_CPU LABEL UTIME STIME HZ": the CPU ticks (user, system; HZ a second) of the
# liggghts-membrane process that runs this through the input's `shell` command (rank 0:
# LIGGGHTS runs `shell` there only), for bench/in.membrane3d_cuboid_cost's timed runs.
p=$$
while [ "$p" -gt 1 ]; do
  case "$(cat "/proc/$p/comm")" in
    liggghts*) echo "BENCH_CPU $1 $(cut -d' ' -f14,15 "/proc/$p/stat") $(getconf CLK_TCK)"; exit 0 ;;
  esac
  p=$(cut -d' ' -f4 "/proc/$p/stat")
done
