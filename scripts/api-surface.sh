#!/usr/bin/env bash
# The size of the physics library's public API and how the application reaches it (issue 41,
# "a facade"), measured the way a reader re-measures it:
#   * the public items: rustdoc's pages for `roughwall` (`cargo doc -p roughwall --no-deps`),
#     one page per public function, type, trait, constant and module, by kind, an item shown
#     at two paths (re-exported) counted once by its kind and name;
#   * the application's use of it: the distinct `roughwall::…` paths named in src/ (use
#     statements expanded, comments dropped), by depth (`roughwall::Item` is depth 1).
# Usage: scripts/api-surface.sh [repository root, default: this one]
set -euo pipefail
ROOT=$(cd "${1:-$(dirname "${BASH_SOURCE[0]}")/..}" && pwd)
cd "$ROOT"
cargo doc -p roughwall --no-deps --quiet --target-dir "$ROOT/target/api-surface" 2>/dev/null
DOC="$ROOT/target/api-surface/doc/roughwall"
echo "public items of roughwall (rustdoc pages; an item re-exported in two places counted once):"
find "$DOC" -name '*.html' ! -name 'all.html' ! -name 'sidebar-items*' |
  sed -E "s|^$DOC/||" |
  awk -F/ '{f = $NF; if (f == "index.html") {print "mod." $(NF-1)} else {sub(/\.html$/, "", f); print f}}' |
  sort -u | cut -d. -f1 | sort | uniq -c |
  awk '{printf "  %-10s %d\n", $2, $1; n += $1} END {printf "  %-10s %d\n", "total", n}'
python3 - "$ROOT/src" <<'PY'
import collections, os, re, sys
def expand(prefix, body):
    out, depth, cur = [], 0, ""
    for ch in body:
        depth += (ch == "{") - (ch == "}")
        if ch == "," and depth == 0:
            out.append(cur.strip()); cur = ""
        else:
            cur += ch
    if cur.strip():
        out.append(cur.strip())
    res = []
    for o in out:
        if "{" in o:
            p, b = o.split("{", 1)
            res += expand(prefix + p, b.rsplit("}", 1)[0])
        else:
            res.append(prefix + o)
    return res
paths = set()
for dp, _, fn in os.walk(sys.argv[1]):
    for f in fn:
        if not f.endswith(".rs"):
            continue
        t = re.sub(r"//[^\n]*", "", open(os.path.join(dp, f)).read())
        for m in re.finditer(r"roughwall::((?:[A-Za-z0-9_]+::)*)(\{[^;]*?\}|[A-Za-z0-9_]+)", t):
            pre, last = m.group(1), m.group(2)
            items = expand(pre, last[1:-1]) if last.startswith("{") else [pre + last]
            for p in items:
                p = p.split(" as ")[0].strip()
                if p.endswith("::self"):
                    p = p[: -len("::self")]
                paths.add(p)
# An associated item (`Type::method`) counts at its type's depth.
def depth(p):
    segs = p.split("::")
    while len(segs) > 1 and segs[-2][:1].isupper():
        segs.pop()
    return len(segs)
by = collections.Counter(depth(p) for p in paths)
print(f"roughwall paths the application (src/) names: {len(paths)}")
for d in sorted(by):
    print(f"  depth {d}: {by[d]}")
PY
