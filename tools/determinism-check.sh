#!/usr/bin/env bash
# Cross-runtime determinism check (docs/determinism.md): flies the same seeded random shots (tools/DeterminismCheck:
# every preset and integrator, bounces, aim solves) on CoreCLR, on Mono, and on Mono with its intrinsics off
# (-O=-intrins: Math calls go to the C library instead of x87 instructions), and fails if any bit of any shot's
# landing, bounce or aim differs. Needs mono (tools/test-mono.sh installs it).
#   bash tools/determinism-check.sh [shots]     (default 100000)
set -euo pipefail
cd "$(dirname "$0")/.."
shots="${1:-100000}"
out="$(mktemp -d)"

dotnet build tools/DeterminismCheck -c Release -nologo -v quiet >/dev/null
bin=artifacts/bin/DeterminismCheck
# All three side by side (two cores: about 4 minutes for 100,000 shots on an idle machine).
dotnet "$bin/release_net10.0/DeterminismCheck.dll" "$shots" "$out/coreclr.txt" > "$out/coreclr.log" & core=$!
mono "$bin/release_net48/DeterminismCheck.exe" "$shots" "$out/mono.txt" > "$out/mono.log" & plain=$!
mono -O=-intrins "$bin/release_net48/DeterminismCheck.exe" "$shots" "$out/mono-nointrins.txt" > "$out/mono-nointrins.log" & nointrins=$!
wait "$core"; wait "$plain"; wait "$nointrins"

status=0
differing() { awk 'NR == FNR { a[FNR] = $0; next } a[FNR] != $0 { c++ } END { print c + 0 }' "$1" "$2"; }
for run in coreclr mono mono-nointrins; do echo "$run: $(cat "$out/$run.log")"; done
for other in mono mono-nointrins; do
  lines=$(wc -l < "$out/$other.txt")
  d=$(differing "$out/coreclr.txt" "$out/$other.txt")
  echo "determinism: coreclr vs $other: $d of $lines shots differ"
  if [ "$d" -ne 0 ] || [ "$lines" -ne "$shots" ]; then
    status=1
    awk 'NR == FNR { a[FNR] = $0; next } a[FNR] != $0 { print "  coreclr: " a[FNR]; print "  " FILENAME ": " $0; if (++c == 3) exit }' "$out/coreclr.txt" "$out/$other.txt"
  fi
done
rm -rf "$out"
exit "$status"
