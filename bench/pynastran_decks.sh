#!/usr/bin/env bash
# How many of the public decks in pyNastran's models/ folder `seflex info` reads (issue 14): every
# .bdf/.dat/.nas file under models/ of a pyNastran checkout or bare mirror, run through
# `seflex info` with a time limit; prints the count by outcome (exit 0 = read, unsupported cards
# listed; 3 = refused with an input error; anything else = crash or hang) and, per deck, the outcome
# and the first line of the error, to a CSV.
#   bench/pynastran_decks.sh SEFLEX PYNASTRAN_GIT_DIR [OUT_CSV] [TIMEOUT_S]
# e.g. bench/pynastran_decks.sh build/apps/seflex /work/.mirror/SteveDoyle2+pyNastran/repo decks.csv
# A bare mirror is read with `git cat-file` file by file (blobs missing from the mirror are skipped
# and counted).
set -uo pipefail
seflex="$(realpath "$1")"
git_dir="$2"
out="${3:-pynastran-decks.csv}"
limit="${4:-60}"
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
commit=$(git --git-dir="$git_dir" rev-parse HEAD)
missing=0
while read -r _ type obj path; do
  [ "$type" = blob ] || continue
  mkdir -p "$tmp/$(dirname "$path")"
  git --git-dir="$git_dir" cat-file blob "$obj" > "$tmp/$path" 2> /dev/null || { rm -f "$tmp/$path"; missing=$((missing + 1)); }
done < <(git --git-dir="$git_dir" ls-tree -r HEAD models)
echo "deck,outcome,exit,message" > "$out"
declare -A count=([read]=0 [refused]=0 [crash]=0 [timeout]=0)
while IFS= read -r deck; do
  rel="${deck#"$tmp"/}"
  msg=$(cd "$(dirname "$deck")" && timeout "$limit" "$seflex" info "$(basename "$deck")" 2>&1 > /dev/null)
  rc=$?
  msg=$(head -1 <<< "$msg")
  case "$rc" in
    0) outcome=read ;;
    3) outcome=refused ;;
    124) outcome=timeout ;;
    *) outcome=crash ;;
  esac
  count[$outcome]=$((count[$outcome] + 1))
  printf '%s,%s,%s,"%s"\n' "$rel" "$outcome" "$rc" "${msg//\"/\'}" >> "$out"
done < <(find "$tmp/models" -type f \( -iname '*.bdf' -o -iname '*.dat' -o -iname '*.nas' \) | sort)
total=$((count[read] + count[refused] + count[crash] + count[timeout]))
echo "# seflex info on pyNastran models/ at $commit ($(date -I)): $total decks ($missing files missing from the mirror)"
echo "read (exit 0): ${count[read]}  refused (exit 3): ${count[refused]}  crash: ${count[crash]}  timeout (${limit} s): ${count[timeout]}"
echo "per deck: $out"
