#!/usr/bin/env bash
# docs.links: no link in README.md or docs/*.md leads out of the repository or to nothing. Each
# Markdown link ](target) and each src="target" outside code blocks: http(s) and mailto links may
# stay (public sites); #anchors stay; any other target must be a relative path that, resolved from
# the file's folder, exists and lies inside the repository. Anywhere in the text (code included),
# a path into another checkout (/work/..., ../shared/...) fails too.
# First a control: a made-up repository with a bad link, one out of the tree and one to /work must
# each fail, and one with good links pass; then the real files.
# usage: docs_links.sh SOURCE_DIR
set -euo pipefail
src=$(cd "${1:?usage: docs_links.sh SOURCE_DIR}" && pwd)

check() {  # check ROOT FILE...: prints each bad link, exit status 1 if any
  python3 - "$@" <<'PY'
import os, re, sys
root = os.path.realpath(sys.argv[1])
LINK = re.compile(r'\]\(\s*<?([^)>\s]+)>?(?:\s+"[^"]*")?\s*\)|\bsrc="([^"]+)"')
OUTSIDE = re.compile(r'(?<![\w.-])(/work/|\.\./shared/)')
bad = 0
for path in sys.argv[2:]:
    rel = os.path.relpath(path, root)
    fence = False
    for n, line in enumerate(open(path, encoding="utf-8"), 1):
        if OUTSIDE.search(line):
            print(f"{rel}:{n}: a path outside the repository: {line.strip()[:120]}"); bad += 1
        if line.lstrip().startswith("```"):
            fence = not fence
            continue
        if fence:
            continue
        text = re.sub(r"`[^`]*`", "", line)  # code spans are not links
        for m in LINK.finditer(text):
            target = m.group(1) or m.group(2)
            if re.match(r"(https?|mailto):", target) or target.startswith("#"):
                continue
            if re.match(r"[a-z][a-z0-9+.-]*:", target, re.I) or target.startswith("/"):
                print(f"{rel}:{n}: {target}: not a relative path in the repository"); bad += 1
                continue
            target = target.split("#")[0].split("?")[0]
            full = os.path.realpath(os.path.join(os.path.dirname(path), target))
            if not (full == root or full.startswith(root + os.sep)):
                print(f"{rel}:{n}: {target}: outside the repository"); bad += 1
            elif not os.path.exists(full):
                print(f"{rel}:{n}: {target}: no such file"); bad += 1
sys.exit(1 if bad else 0)
PY
}

# The control.
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
mkdir -p "$tmp/outside" "$tmp/repo/docs"
touch "$tmp/outside/x.md" "$tmp/repo/docs/here.md"
printf '# ok\n[here](docs/here.md) [site](https://example.org/) [top](#ok)\n' > "$tmp/repo/README.md"
check "$tmp/repo" "$tmp/repo/README.md" >/dev/null || { echo "control: good links were refused"; exit 1; }
for bad_link in '[gone](docs/gone.md)' '[out](../outside/x.md)' '[abs](/work/shared/x.md)' 'see `../shared/design/A.md`'; do
  printf '# bad\n%s\n' "$bad_link" > "$tmp/repo/docs/bad.md"
  if check "$tmp/repo" "$tmp/repo/docs/bad.md" >/dev/null; then
    echo "control: $bad_link was not found bad"; exit 1
  fi
done
echo "control: a missing file, a link out of the tree, /work and ../shared each fail"

# The repository's README and docs.
files=("$src/README.md")
for f in "$src"/docs/*.md; do files+=("$f"); done
if ! check "$src" "${files[@]}"; then
  echo "docs.links: fix or drop the links above (README.md, docs/*.md)"; exit 1
fi
echo "docs.links: ${#files[@]} files, every link inside the repository"
