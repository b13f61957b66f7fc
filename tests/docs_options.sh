#!/usr/bin/env bash
# docs.options: docs/options.md is what `penumbra options --markdown` prints from the option table
# (src/plan/option_table.cpp) now; a stale page fails with the command that refreshes it. A
# control first: the same comparison against a copy with one line changed must fail.
# usage: docs_options.sh PENUMBRA SOURCE_DIR
set -euo pipefail
cli=${1:?usage: docs_options.sh PENUMBRA SOURCE_DIR}
src=${2:?usage: docs_options.sh PENUMBRA SOURCE_DIR}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

"$cli" options --markdown > "$tmp/options.md"
"$cli" options --markdown > "$tmp/again.md"
cmp -s "$tmp/options.md" "$tmp/again.md" || { echo "docs.options: two runs of penumbra options --markdown differ"; exit 1; }
grep -q '^| `--technique` |' "$tmp/options.md" || { echo "docs.options: no --technique row in the generated page"; exit 1; }

# The control: a page with one line changed is stale.
sed '0,/^| `--technique` |/s//| `--technique` (edited) |/' "$tmp/options.md" > "$tmp/edited.md"
if cmp -s "$tmp/options.md" "$tmp/edited.md"; then
  echo "control: an edited page was not found stale"; exit 1
fi
echo "control: a page with one row edited is found stale"

if ! diff -u "$src/docs/options.md" "$tmp/options.md"; then
  echo "docs.options: docs/options.md is stale (the option table changed). Refresh it from the repository root:"
  echo "  build/penumbra options --markdown > docs/options.md"
  exit 1
fi
echo "docs.options: docs/options.md matches the option table ($(grep -c '^| `--' "$tmp/options.md") options)"
