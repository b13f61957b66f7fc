#!/usr/bin/env python3
"""Print what each page of the web site downloads: its wasm and JavaScript, raw and gzipped
(gzip -9, as a static server with compression would send it), and the page's total with its
HTML and CSS.

usage: payload.py SITE_DIR [--markdown] [--max-gz BYTES]
--max-gz: exit 1, naming each page, where a page's wasm and scripts gzipped pass BYTES (the web.payload
test holds issue 58's 200 KB a page with it).
A page's files are the local src=/href= references in its HTML, plus the .wasm that a referenced
Emscripten .js loads (the .js of the same name).
"""
import gzip
import pathlib
import re
import sys

REF = re.compile(r'(?:src|href)="([^"#?:]+)"')


def sizes(path: pathlib.Path) -> tuple[int, int]:
    data = path.read_bytes()
    return len(data), len(gzip.compress(data, compresslevel=9, mtime=0))


def page_files(site: pathlib.Path, page: pathlib.Path) -> list[pathlib.Path]:
    files = [page]
    for ref in REF.findall(page.read_text()):
        f = site / ref
        if f.is_file() and f.suffix in (".js", ".css") and f not in files:
            files.append(f)
            wasm = f.with_suffix(".wasm")
            if f.suffix == ".js" and wasm.is_file() and wasm not in files:
                files.append(wasm)
    return files


def kib(n: int) -> str:
    return f"{n / 1024:.1f} KiB"


def main() -> None:
    site = pathlib.Path(sys.argv[1])
    args = sys.argv[2:]
    markdown = "--markdown" in args
    max_gz = None
    if "--max-gz" in args:
        at = args.index("--max-gz") + 1
        if at >= len(args) or not args[at].isdigit():
            sys.exit("payload: --max-gz needs a whole number of bytes")
        max_gz = int(args[at])
    pages = sorted(p for p in site.glob("*.html"))
    if not pages:
        sys.exit(f"payload: no pages in {site}")
    rows = []
    for page in pages:
        files = page_files(site, page)
        wasm = [sizes(f) for f in files if f.suffix == ".wasm"]
        js = [sizes(f) for f in files if f.suffix == ".js"]
        total = [sizes(f) for f in files]
        s = lambda xs, i: sum(x[i] for x in xs)  # noqa: E731
        rows.append((page.name, s(wasm, 0), s(wasm, 1), s(js, 0), s(js, 1), s(total, 0), s(total, 1)))
    if markdown:
        print("| page | wasm raw | wasm gzip | js raw | js gzip | wasm+js raw | wasm+js gzip | page total raw | page total gzip |")
        print("|---|---|---|---|---|---|---|---|---|")
        for name, wr, wg, jr, jg, tr, tg in rows:
            print(f"| {name} | {kib(wr)} | {kib(wg)} | {kib(jr)} | {kib(jg)} | {kib(wr + jr)} | {kib(wg + jg)} "
                  f"| {kib(tr)} | {kib(tg)} |")
        return
    print(f"payload of each page in {site} (gzip -9); each exercise page has a module of its own (NAME.js, NAME.wasm):")
    print(f"  {'page':<14} {'wasm raw':>10} {'wasm gz':>10} {'js raw':>10} {'js gz':>10} "
          f"{'wasm+js raw':>12} {'wasm+js gz':>11} {'all raw':>10} {'all gz':>10}")
    for name, wr, wg, jr, jg, tr, tg in rows:
        print(f"  {name:<14} {wr:>10} {wg:>10} {jr:>10} {jg:>10} {wr + jr:>12} {wg + jg:>11} {tr:>10} {tg:>10}")
    print("  (bytes; 'all' adds the page's HTML and CSS)")
    loads = sorted(r[2] + r[4] for r in rows if r[2])
    if loads:
        print(f"  wasm+js gzipped: {loads[0]} to {loads[-1]} B, median {loads[len(loads) // 2]} B over {len(loads)} pages "
              "(issue 58's goal: at most 200 KB a page)")
    # The shader lab's files (lab/: its script and style, the editor's), which a page loads only
    # when the lab's panel opens: not in any page's figures above.
    lab = sorted(f for f in (site / "lab").glob("*") if f.suffix in (".js", ".css")) if (site / "lab").is_dir() else []
    if lab:
        raw = sum(sizes(f)[0] for f in lab)
        gz = sum(sizes(f)[1] for f in lab)
        names = ", ".join(f.name for f in lab)
        print(f"  the shader lab's panel, loaded when opened: {raw} B raw, {gz} B gzipped ({names})")
    if max_gz is not None:
        over = [(name, wg + jg) for name, _, wg, _, jg, _, _ in rows if wg + jg > max_gz]
        for name, n in over:
            print(f"payload: {name} loads {n} B of wasm and scripts gzipped, over the limit of {max_gz} B",
                  file=sys.stderr)
        if over:
            sys.exit(1)
        print(f"  every page within {max_gz} B gzipped (wasm+js)")


if __name__ == "__main__":
    main()
