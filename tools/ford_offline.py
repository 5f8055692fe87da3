"""Make FORD's pages render offline (HPC clusters, laptops on a train).

FORD 7 loads Bootstrap and MathJax from a CDN. This rewrites every page of the API
reference to use a local copy of Bootstrap (Debian's libjs-bootstrap5, installed by
tools/setup.sh) in doc/api/vendor/, and drops the MathJax scripts: the `!>` comments of
src/ hold no TeX (this script fails when one does, so that MathJax is vendored then).
No link to another host remains in a page's <head>.

Usage: python3 tools/ford_offline.py API_DIR SRC_DIR
"""
import pathlib
import re
import shutil
import sys

BOOTSTRAP = pathlib.Path("/usr/share/javascript/bootstrap5")
ASSETS = {"css/bootstrap.min.css": "vendor/bootstrap.min.css",
          "js/bootstrap.bundle.min.js": "vendor/bootstrap.bundle.min.js"}
CDN_CSS = re.compile(r'<link href="https://cdn\.jsdelivr\.net/npm/bootstrap@[^"]*/bootstrap\.min\.css"'
                     r'[^>]*>', re.DOTALL)
CDN_JS = re.compile(r'<script src="https://cdn\.jsdelivr\.net/npm/bootstrap@[^"]*/bootstrap\.bundle\.min\.js"'
                    r'[^>]*></script>', re.DOTALL)
MATHJAX = re.compile(r'\s*<!-- MathJax -->\s*<script type="text/x-mathjax-config">.*?</script>'
                     r'\s*<script src="https://cdn\.jsdelivr\.net/npm/mathjax@[^"]*"[^>]*></script>',
                     re.DOTALL)
TEX = re.compile(r"!>.*(\\\(|\\\[|\$\$)")


def main(api, src):
    tex = [f"{f.name}:{n}" for f in sorted(src.glob("*.f90"))
           for n, line in enumerate(f.read_text().splitlines(), 1) if TEX.search(line)]
    if tex:
        sys.exit(f"tools/ford_offline.py: TeX in doc comments ({', '.join(tex[:5])}): "
                 "vendor MathJax (Debian libjs-mathjax) before dropping its script")
    for rel in ASSETS:
        if not (BOOTSTRAP / rel).is_file():
            sys.exit(f"tools/ford_offline.py: {BOOTSTRAP / rel} missing "
                     "(apt-get install libjs-bootstrap5; bash tools/setup.sh does it)")
    (api / "vendor").mkdir(exist_ok=True)
    for rel, target in ASSETS.items():
        shutil.copyfile(BOOTSTRAP / rel, api / target)
    pages = sorted(api.rglob("*.html"))
    for page in pages:
        text = page.read_text()
        up = "../" * (len(page.relative_to(api).parts) - 1) or "./"
        text, n_css = CDN_CSS.subn(f'<link href="{up}vendor/bootstrap.min.css" rel="stylesheet">', text)
        text, n_js = CDN_JS.subn(f'<script src="{up}vendor/bootstrap.bundle.min.js"></script>', text)
        text = MATHJAX.sub("", text)
        head = text.split("</head>", 1)[0]
        remote = re.findall(r'(?:href|src)="(https?://[^"]+)"', head)
        if remote or n_css != 1 or n_js != 1:
            sys.exit(f"tools/ford_offline.py: {page}: remote assets left in <head>: {remote}")
        page.write_text(text)
    print(f"ford_offline: {len(pages)} pages use vendor/ (Bootstrap from {BOOTSTRAP}), no MathJax")


if __name__ == "__main__":
    main(pathlib.Path(sys.argv[1]), pathlib.Path(sys.argv[2]))
