"""Bring the viewers' JavaScript library in from the npm registry, checked by its hash.

three.js is pinned below (version, the tarball's npm integrity hash). ``python
tools/vendor_js.py`` fetches the release tarball with npm's own client (``npm pack``), checks
its sha512 against the pin, and copies the one file the viewers use and the licence into
``screwkit/static/vendor/``, with ``three.json`` recording the version and each file's
sha256. ``python tools/vendor_js.py --check`` fetches it again and fails unless the committed
files equal the release's bytes. Nothing is taken from a CDN; the page never loads a URL.
"""
import argparse
import base64
import hashlib
import json
import pathlib
import subprocess
import sys
import tarfile
import tempfile

ROOT = pathlib.Path(__file__).resolve().parents[1]
VENDOR = ROOT / "screwkit" / "static" / "vendor"
PACKAGE = "three"
VERSION = "0.159.0"
INTEGRITY = (
    "sha512-eCmhlLGbBgucuo4VEA9IO3Qpc7dh8Bd4VKzr7WfW4+8hMcIfoAVi1ev0pJYN9PTTsCslbcKgBwr2wNZ1EvLInA=="
)
# file in the tarball -> name under screwkit/static/vendor/
FILES = {
    "package/build/three.module.min.js": "three.module.min.js",
    "package/LICENSE": "three.LICENSE",
}


def fetch_tarball(folder):
    """The pinned release's tarball (bytes), fetched by ``npm pack``, its sha512 checked."""
    spec = f"{PACKAGE}@{VERSION}"
    subprocess.run(["npm", "pack", spec, "--silent", "--pack-destination", str(folder)],
                   check=True, stdout=subprocess.DEVNULL, timeout=600)
    data = (pathlib.Path(folder) / f"{PACKAGE}-{VERSION}.tgz").read_bytes()
    got = "sha512-" + base64.b64encode(hashlib.sha512(data).digest()).decode()
    if got != INTEGRITY:
        sys.exit(f"{spec}: the tarball's integrity is {got}, the pin says {INTEGRITY}")
    return pathlib.Path(folder) / f"{PACKAGE}-{VERSION}.tgz"


def release_files():
    """{vendored name: bytes} of the pinned release."""
    with tempfile.TemporaryDirectory() as folder:
        with tarfile.open(fetch_tarball(folder)) as archive:
            return {name: archive.extractfile(member).read() for member, name in FILES.items()}


def manifest(files):
    return {"package": PACKAGE, "version": VERSION, "integrity": INTEGRITY,
            "sha256": {name: hashlib.sha256(data).hexdigest() for name, data in files.items()}}


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--check", action="store_true",
                        help="fail unless the committed files equal the pinned release's")
    args = parser.parse_args()
    files = release_files()
    if args.check:
        wrong = [name for name, data in files.items()
                 if not (VENDOR / name).is_file() or (VENDOR / name).read_bytes() != data]
        recorded = json.loads((VENDOR / "three.json").read_text())
        if recorded != manifest(files):
            wrong.append("three.json")
        if wrong:
            sys.exit(f"screwkit/static/vendor/: {wrong} differ from {PACKAGE}@{VERSION} "
                     "(run tools/vendor_js.py)")
        print(f"screwkit/static/vendor/ equals {PACKAGE}@{VERSION} from npm "
              f"({', '.join(files)})")
        return
    VENDOR.mkdir(parents=True, exist_ok=True)
    for name, data in files.items():
        (VENDOR / name).write_bytes(data)
    (VENDOR / "three.json").write_text(json.dumps(manifest(files), indent=2) + "\n")
    print(f"vendored {PACKAGE}@{VERSION}: {', '.join(files)}")


if __name__ == "__main__":
    main()
