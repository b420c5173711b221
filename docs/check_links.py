"""Checks a built HTML site for broken internal links: every relative href and src of every page
names a file that exists, and every #fragment names an id in its target page.

Usage: python3 docs/check_links.py HTML_DIR   (exit 1 listing each broken link; tools/build-docs.sh)
"""
import sys
from html.parser import HTMLParser
from pathlib import Path
from urllib.parse import unquote, urlsplit


class _Page(HTMLParser):
    """The ids and the local links (href, src) of one HTML page."""

    def __init__(self):
        super().__init__()
        self.ids, self.links = set(), []

    def handle_starttag(self, tag, attrs):
        for name, value in attrs:
            if name in ("id", "name") and value:
                self.ids.add(value)
            elif name in ("href", "src") and value:
                self.links.append(value)


def _parse(path, cache):
    if path not in cache:
        page = _Page()
        page.feed(path.read_text(encoding="utf-8", errors="replace"))
        cache[path] = page
    return cache[path]


def broken_links(site):
    """Returns 'page: link (why)' for each link that does not resolve."""
    cache, broken = {}, []
    for page_path in sorted(site.rglob("*.html")):
        for link in _parse(page_path, cache).links:
            parts = urlsplit(link)
            if parts.scheme or parts.netloc or link.startswith(("mailto:", "javascript:", "data:")):
                continue
            target = page_path if not parts.path else (page_path.parent / unquote(parts.path)).resolve()
            if target.is_dir():
                target = target / "index.html"
            where = page_path.relative_to(site)
            if not target.is_file():
                broken.append(f"{where}: {link} (no such file)")
            elif parts.fragment and target.suffix == ".html" and unquote(parts.fragment) not in _parse(target, cache).ids:
                broken.append(f"{where}: {link} (no id {parts.fragment!r} in {target.name})")
    return broken


def main(argv):
    if len(argv) != 2 or not Path(argv[1]).is_dir():
        print("usage: check_links.py HTML_DIR", file=sys.stderr)
        return 2
    site = Path(argv[1]).resolve()
    broken = broken_links(site)
    for line in broken:
        print(f"check_links: broken link in {line}", file=sys.stderr)
    pages = len(list(site.rglob("*.html")))
    if not broken:
        print(f"check_links: {pages} pages, every internal link resolves")
    return 1 if broken else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
