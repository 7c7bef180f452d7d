#!/usr/bin/env bash
# Packs the library and the CLI tool and fails unless each .nupkg carries what a newcomer trusts: the README,
# the licence expression, the repository URL and type, the project URL, tags, and a symbols package (.snupkg).
# Run by .ci/run; also by hand: bash tools/check-packages.sh [output-folder]
set -euo pipefail
cd "$(dirname "$0")/.."
out="${1:-$(mktemp -d)}"
dotnet pack src/MagnusBall/Runtime/MagnusBall.csproj -c Release -o "$out" --nologo -v quiet
dotnet pack src/MagnusBall.Cli/MagnusBall.Cli.csproj -c Release -o "$out" --nologo -v quiet

failed=0
check() { # package nuspec-text what pattern
  if ! grep -Eq "$4" <<<"$2"; then echo "check-packages: $1: $3 missing (expected /$4/)" >&2; failed=1; fi
}
for id in MagnusBall MagnusBall.Cli; do
  nupkg=$(ls "$out"/"$id".[0-9]*.nupkg 2>/dev/null | sed -n 1p)
  if [ -z "$nupkg" ]; then echo "check-packages: no $id .nupkg in $out" >&2; failed=1; continue; fi
  nuspec=$(unzip -p "$nupkg" "$id.nuspec")
  check "$id" "$nuspec" "readme" '<readme>README.md</readme>'
  check "$id" "$nuspec" "licence expression" '<license type="expression">MIT</license>'
  check "$id" "$nuspec" "repository URL and type" '<repository type="git" url="https://[^"]+"'
  check "$id" "$nuspec" "project URL" '<projectUrl>https://[^<]+</projectUrl>'
  check "$id" "$nuspec" "tags" '<tags>[^<]*magnus[^<]*</tags>'
  # The listing is read whole first: `unzip -l | grep -q` under pipefail fails at random when grep exits before unzip
  # has written everything (SIGPIPE).
  listing=$(unzip -l "$nupkg")
  grep -q ' README.md$' <<<"$listing" || { echo "check-packages: $id: README.md not inside the package" >&2; failed=1; }
  [ -f "${nupkg%.nupkg}.snupkg" ] || { echo "check-packages: $id: no symbols package ${nupkg%.nupkg}.snupkg" >&2; failed=1; }
done
[ "$failed" -eq 0 ] && echo "check-packages: MagnusBall and MagnusBall.Cli packages carry readme, licence, repository, project URL, tags and symbols ($out)"
exit "$failed"
