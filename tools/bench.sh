#!/usr/bin/env bash
# Builds animator-bench and the plugins it bakes with, runs the full benchmark of the physics
# backends (docs/performance.md) and draws its plots with gnuplot (installed here if missing:
# gnuplot-nox, no display needed):
#   docs/bench/*.csv         the tables (written by animator-bench)
#   docs/bench/output.txt    what animator-bench printed
#   docs/bench/machine.txt   the machine: nproc, CPU model, memory, load before the run
#   docs/bench/exact.png     error (log) against wall time (log) per exact scene, one curve per backend
#   docs/bench/gas.png       the gas: wall time per simulated second and collisions per second against N
# Extra arguments go to animator-bench (e.g. --runs 7, --only exact, --quick).
# Environment: BUILD_DIR (default build-bench), JOBS (default 2), OUT (default docs/bench);
# PLOTS_ONLY=1 draws the plots again from the CSVs already in OUT, without building or running.
set -euo pipefail
cd "$(dirname "$0")/.."
build=${BUILD_DIR:-build-bench}
out=${OUT:-docs/bench}

if ! command -v gnuplot >/dev/null; then
  sudo=""
  [ "$(id -u)" -ne 0 ] && sudo=sudo
  $sudo apt-get install -y gnuplot-nox || { $sudo apt-get update && $sudo apt-get install -y gnuplot-nox; }
fi

if [ -z "${PLOTS_ONLY:-}" ]; then
  cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
  cmake --build "$build" -j "${JOBS:-2}" --target animator-bench

  mkdir -p "$out"
  {
    echo "date: $(date -u '+%Y-%m-%d %H:%M UTC')"
    echo "nproc: $(nproc)"
    echo "cpu: $(lscpu | sed -n 's/^Model name:[[:space:]]*//p' | head -1)"
    echo "memory: $(free -h | awk '/^Mem:/ {print $2}')"
    echo "load before the run: $(cut -d' ' -f1-3 /proc/loadavg)"
    echo "build: RelWithDebInfo ($(c++ --version | head -1))"
    echo "command: tools/bench.sh $*"
  } > "$out/machine.txt"
  nice -n 5 "$build/bin/animator-bench" --out "$out" "$@" | tee "$out/output.txt"
  echo "load after the run: $(cut -d' ' -f1-3 /proc/loadavg)" >> "$out/machine.txt"
fi

# The plots. Each scene's main measure (the first animator-bench lists for it); physics.custom's
# errors of exactly 0 are drawn at 1e-17, the bottom of the axis.
[ -f "$out/exact.csv" ] || exit 0
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
plots=""
i=0
while IFS='|' read -r scene measure; do
  for backend in physics.custom physics.bullet; do
    awk -F, -v s="$scene" -v m="$measure" -v b="$backend" \
      '$1 == s && $2 == m && $3 == b { e = $5 + 0; if (e < 1e-17) e = 1e-17; print $6, e, ($4 > 0 ? sprintf("1/%d", 1 / $4 + 0.5) : "exact") }' \
      "$out/exact.csv" > "$tmp/$scene-$backend.dat"
  done
  i=$((i + 1))
  plots="$plots
set title '$scene: $measure'
plot '$tmp/$scene-physics.bullet.dat' using 1:2 with linespoints lw 2 pt 7 lc rgb '#c0392b' title 'physics.bullet (step)', \
     '' using 1:2:3 with labels offset 0,1 font ',8' notitle, \
     '$tmp/$scene-physics.custom.dat' using 1:2 with points pt 5 ps 2 lc rgb '#2471a3' title 'physics.custom (exact)'"
done <<'SCENES'
drop|apex (relative)
oblique|velocity (relative)
cradle|position (m)
box|position (m)
wall|lag at 20 m/s (m)
floor|vertical speed (m/s)
SCENES

gnuplot <<EOF
set terminal pngcairo size 1500,950 font ',10'
set output '$out/exact.png'
set datafile separator whitespace
set logscale xy
set format y '10^{%T}'
set format x '10^{%T}'
set xlabel 'wall time of the scene (ms, median)'
set ylabel 'error against the closed form'
set key top left
set grid
set yrange [1e-17:10]
set multiplot layout 2,3 title 'Error against run time: physics.custom (one point: exact) and physics.bullet at steps 1/60 .. 1/16000 s'
$plots
unset multiplot
EOF

if [ -f "$out/gas.csv" ]; then
  for backend in physics.custom physics.bullet reference; do
    awk -F, -v b="$backend" '$1 == b { print $2, $6, $9 }' "$out/gas.csv" > "$tmp/gas-$backend.dat"
  done
  gnuplot <<EOF
set terminal pngcairo size 1300,500 font ',10'
set output '$out/gas.png'
set logscale xy
set grid
set key top left
set xlabel 'N balls'
set multiplot layout 1,2 title 'A gas of N balls in a box (physics.bullet at 1/1000 s)'
set title 'wall time per simulated second'
set ylabel 's'
plot '$tmp/gas-physics.custom.dat' using 1:2 with linespoints lw 2 pt 5 lc rgb '#2471a3' title 'physics.custom', \
     '$tmp/gas-physics.bullet.dat' using 1:2 with linespoints lw 2 pt 7 lc rgb '#c0392b' title 'physics.bullet', \
     '$tmp/gas-reference.dat' using 1:2 with linespoints lw 2 pt 9 lc rgb '#7f8c8d' title 'reference program (bench)'
set title 'collisions per second of wall time'
set ylabel 'collisions / s'
set yrange [100:1e7]
set format y '10^{%T}'
plot '$tmp/gas-physics.custom.dat' using 1:3 with linespoints lw 2 pt 5 lc rgb '#2471a3' title 'physics.custom', \
     '$tmp/gas-physics.bullet.dat' using 1:3 with linespoints lw 2 pt 7 lc rgb '#c0392b' title 'physics.bullet', \
     '$tmp/gas-reference.dat' using 1:3 with linespoints lw 2 pt 9 lc rgb '#7f8c8d' title 'reference program (bench)', \
     1e6 with lines dt 2 lc rgb 'black' title 'target 10^6'
unset multiplot
EOF
fi
echo "tools/bench.sh: tables and plots in $out"
