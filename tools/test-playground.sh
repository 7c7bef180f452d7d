#!/usr/bin/env bash
# The browser playground's real-browser tests (docs/playground.md): installs Debian's Chromium when it is missing,
# publishes samples/Playground (Blazor WebAssembly, the .NET interpreter, no workload) into artifacts/playground-site,
# prints its Brotli download size, and runs tests/MagnusBall.Playground.Tests (Playwright driving /usr/bin/chromium
# against the app served on 127.0.0.1). .ci/run calls it after the Mono suite.
#   bash tools/test-playground.sh
set -euo pipefail
cd "$(dirname "$0")/.."

if [ ! -x /usr/bin/chromium ]; then
  echo "playground: installing chromium" >&2
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -qq
  apt-get install -y -qq chromium >/dev/null
fi
/usr/bin/chromium --version 2>/dev/null

site="$(pwd)/artifacts/playground-site"
rm -rf "$site"
start=$(date +%s)
dotnet publish samples/Playground -c Release -o "$site" -nologo -v quiet
echo "playground: published in $(( $(date +%s) - start )) s; download $(find "$site/wwwroot" -name '*.br' -printf '%s\n' | awk '{ s += $1 } END { printf "%.2f MB", s / 1e6 }') Brotli"

start=$(date +%s)
MAGNUSBALL_PLAYGROUND_SITE="$site" dotnet test tests/MagnusBall.Playground.Tests --logger "console;verbosity=normal" --logger trx --results-directory "${PLAYGROUND_RESULTS:-artifacts/playground-results}"
echo "playground: tests in $(( $(date +%s) - start )) s"
