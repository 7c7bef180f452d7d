#!/usr/bin/env bash
# Writes the Unity .meta file of every file and folder in the MagnusBall package (src/MagnusBall) that has
# none, except in Documentation~, which Unity never imports. Unity ignores files without a .meta in a package it takes
# from a git URL (such packages are read-only, so Unity cannot write the .meta itself). Samples~ is not imported either,
# but Unity copies a sample's folder with its .meta files into Assets/ when the user imports it, so everything inside
# Samples~/<sample>/ gets one too: its scene refers to its scripts by these GUIDs (Samples~ and the sample folders
# themselves get none; Unity gives the copied folder its own). GUIDs are derived from the path (MD5), so running
# this twice, or on two machines, gives the same files. Run it after adding a file to src/MagnusBall:
#   bash tools/write-unity-meta.sh
set -euo pipefail
cd "$(dirname "$0")/.."
root=src/MagnusBall
written=0

guid() { printf '%s' "com.magnusball.core/$1" | md5sum | cut -c1-32; }

write() { # path importer-block
  local path="$1" block="$2" rel="${1#"$root"/}"
  [ -e "$path.meta" ] && return 0
  printf 'fileFormatVersion: 2\nguid: %s\n%s\n' "$(guid "$rel")" "$block" > "$path.meta"
  written=$((written + 1))
}

importer() { # name [extra lines]
  printf '%s:\n%s  externalObjects: {}\n  userData: \n  assetBundleName: \n  assetBundleVariant: \n' "$1" "${2:-}"
}

mono=$'  serializedVersion: 2\n  defaultReferences: []\n  executionOrder: 0\n  icon: {instanceID: 0}\n'

while IFS= read -r -d '' dir; do
  [ "$dir" = "$root" ] && continue
  case "${dir#"$root"/}" in Samples~/*/*) ;; Samples~ | Samples~/*) continue ;; esac
  write "$dir" "folderAsset: yes
$(importer DefaultImporter)"
done < <(find "$root" \( -name bin -o -name obj -o -name 'Documentation~' -o -name '.*' \) -prune -o -type d -print0)

while IFS= read -r -d '' file; do
  case "$file" in
    *.meta) continue ;;
    *.cs) write "$file" "$(importer MonoImporter "$mono")" ;;
    */package.json) write "$file" "$(importer PackageManifestImporter)" ;;
    *.asmdef) write "$file" "$(importer AssemblyDefinitionImporter)" ;;
    *) write "$file" "$(importer DefaultImporter)" ;;
  esac
done < <(find "$root" \( -name bin -o -name obj -o -name 'Documentation~' -o -name '.*' \) -prune -o -type f -print0)

echo "wrote $written .meta file(s) under $root"
