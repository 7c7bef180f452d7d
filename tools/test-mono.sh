#!/usr/bin/env bash
# Runs the MagnusBall.Tests suite under Debian's Mono (6.8), against the same netstandard2.1 MagnusBall.dll the
# normal build makes, then the cross-runtime determinism check (tools/determinism-check.sh, 100,000 shots).
# Installs mono-devel with apt-get when `mono` is missing. Arguments are passed to the test program
# (regular expressions on full test names) and skip the determinism check. .ci/run calls it after `dotnet test`.
#   bash tools/test-mono.sh                     # the whole suite
#   bash tools/test-mono.sh 'DormandPrince54'   # a part
set -euo pipefail
cd "$(dirname "$0")/.."

if ! command -v mono >/dev/null 2>&1 || [ ! -f /usr/lib/mono/4.5/Facades/netstandard.dll ]; then
  echo "mono: installing mono-devel" >&2
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -qq
  apt-get install -y -qq mono-devel >/dev/null
fi
mono --version | sed -n 1p

dotnet build tests/MagnusBall.Tests.Mono -c Release -nologo -v quiet
mono artifacts/bin/MagnusBall.Tests.Mono/release/MagnusBall.Tests.exe "$@"

# The same shots, bit for bit, on CoreCLR, Mono and Mono without intrinsics (not for a filtered run).
if [ "$#" -eq 0 ]; then
  bash tools/determinism-check.sh
fi
