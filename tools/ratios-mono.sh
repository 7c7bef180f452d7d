#!/usr/bin/env bash
# Issue 11's headline ratios under Mono (the runtime family Unity ships): builds the benchmarks' "ratios" mode as a
# netstandard2.1 library, compiles a two-line launcher with Mono's mcs against it, and runs it with mono.
# Usage: bash tools/ratios-mono.sh [rounds] [seconds per workload]     (needs dotnet and mono-devel)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
out="$root/artifacts/bin/MagnusBall.Ratios.Mono/release"
dotnet build "$root/benchmarks/MagnusBall.Ratios.Mono" -c Release -v quiet -nologo >/dev/null
facades="$(dirname "$(command -v mono)")/../lib/mono/4.5/Facades"
mcs -nologo -optimize+ -out:"$out/Launcher.exe" -r:"$out/MagnusBall.Ratios.dll" -r:"$facades/netstandard.dll" \
    "$root/benchmarks/MagnusBall.Ratios.Mono/Launcher.cs"
cd "$out"
exec mono --optimize=all Launcher.exe "${1:-5}" "${2:-0.25}"
