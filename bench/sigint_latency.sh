#!/bin/bash
# Ctrl-C latency of a cook (bench/RESULTS.md, "Ctrl-C latency"): starts `tfd cook GRAPH`,
# sends SIGINT after DELAY seconds, prints the exit code, the time from the signal to the exit
# and the progress line showing what was running.
#   bench/sigint_latency.sh build/apps/tfd /tmp/d1m.tfd.json 12
set -u
tfd=$1 graph=$2 delay=$3
out=$(mktemp -d)
"$tfd" cook "$graph" --out "$out" --progress-interval 0.5 2>"$out/err.txt" >/dev/null &
pid=$!
sleep "$delay"
running=$(grep -v '^tfd' "$out/err.txt" | tail -1)
t0=$(date +%s.%N)
kill -INT "$pid"
wait "$pid"
rc=$?
t1=$(date +%s.%N)
echo "after ${delay} s: exit $rc, signal -> exit $(echo "$t1 - $t0" | bc) s; running: $running"
rm -rf "$out"
