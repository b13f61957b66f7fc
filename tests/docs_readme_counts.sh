#!/usr/bin/env bash
# docs.readme_counts: every count README.md states that the code can give is the code's count.
#   "N techniques"  the choices of --technique in the option table (`penumbra options`), and the
#                   README's technique table has one row per technique, each named
#   "N options"     the option table's options (`penumbra options`, one a line)
#   "N exercises"   the exercise list (examples/exercises/list.h), and web/thumbs has a picture of each
#   "N PNGs"        what `penumbra gallery` writes (run small, into a temporary folder)
# Each phrase must appear at least once and every occurrence must hold the code's number. A control
# first: a copy of README.md with one count off by one must fail.
# usage: docs_readme_counts.sh PENUMBRA SOURCE_DIR
set -euo pipefail
cli=${1:?usage: docs_readme_counts.sh PENUMBRA SOURCE_DIR}
src=${2:?usage: docs_readme_counts.sh PENUMBRA SOURCE_DIR}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# What the code says.
"$cli" options > "$tmp/options.tsv"
options=$(wc -l < "$tmp/options.tsv")
techniques_list=$(awk -F'\t' '$1 == "technique" { print $4 }' "$tmp/options.tsv" | tr -d ' ' | tr ',' ' ')
techniques=$(wc -w <<< "$techniques_list")
exercise_names=$(grep -oE '^ *X\([a-z0-9]+\)' "$src/examples/exercises/list.h" | grep -oE '[a-z0-9]+\)' | tr -d ')')
exercises=$(wc -w <<< "$exercise_names")
"$cli" gallery --size 16x16 --map-size 16 --out-dir "$tmp/gallery" > "$tmp/gallery.log" 2>/dev/null
pngs=$(find "$tmp/gallery" -name '*.png' | wc -l)
grep -q "wrote $pngs images" "$tmp/gallery.log" || { echo "gallery: its count and its files differ: $(cat "$tmp/gallery.log")"; exit 1; }
[ "$techniques" -gt 0 ] && [ "$options" -gt 0 ] && [ "$exercises" -gt 0 ] && [ "$pngs" -gt 0 ] ||
  { echo "could not count: techniques=$techniques options=$options exercises=$exercises pngs=$pngs"; exit 1; }
echo "the code: $techniques techniques ($techniques_list), $options options, $exercises exercises, $pngs PNGs"

# check FILE: each stated count against the code's; prints each difference, status 1 if any.
check() {
  local file=$1 bad=0
  for pair in "techniques:$techniques" "options:$options" "exercises:$exercises" "PNGs:$pngs"; do
    local word=${pair%%:*} want=${pair#*:}
    local said
    said=$(grep -oE "\b[0-9]+ $word\b" "$file" | awk '{print $1}' || true)
    if [ -z "$said" ]; then echo "$(basename "$file"): no \"N $word\""; bad=1; continue; fi
    for n in $said; do
      [ "$n" = "$want" ] || { echo "$(basename "$file"): says $n $word, the code has $want"; bad=1; }
    done
  done
  # The technique table: one row per technique (| `name` | ...), no other.
  local rows
  rows=$(grep -oE '^\| `[a-z0-9-]+`( \(default\))? \|' "$file" | grep -oE '`[a-z0-9-]+`' | tr -d '`' | sort)
  if [ "$rows" != "$(tr ' ' '\n' <<< "$techniques_list" | sed '/^$/d' | sort)" ]; then
    echo "$(basename "$file"): the technique table's rows ($(echo $rows)) are not the techniques ($techniques_list)"; bad=1
  fi
  return $bad
}

# The control: one count off by one fails.
sed -E "0,/\b$pngs PNGs\b/s//$((pngs + 1)) PNGs/" "$src/README.md" > "$tmp/README.md"
if check "$tmp/README.md" > "$tmp/control.log"; then
  echo "control: a README that says $((pngs + 1)) PNGs passed"; exit 1
fi
echo "control: $(cat "$tmp/control.log")"

# The exercises' pictures on the pages' index.
for name in $exercise_names; do
  [ -f "$src/web/thumbs/$name.png" ] || { echo "web/thumbs/$name.png is missing (bash scripts/thumbs.sh)"; exit 1; }
done

if ! check "$src/README.md"; then
  echo "docs.readme_counts: README.md's counts differ from the code's"; exit 1
fi
echo "docs.readme_counts: README.md's counts are the code's"
