"""Bring the viewers' JavaScript libraries in from the npm registry, checked by their
hash.

three.js and tiny-inflate are pinned below (version, the tarball's npm integrity hash).
``python tools/vendor_js.py`` fetches each release tarball with npm's own client (``npm
pack``), checks its sha512 against the pin, and copies the files the viewers use and
their licences into ``screwkit/static/vendor/``, with ``vendor.json`` recording the
versions and each file's sha256. ``python tools/vendor_js.py --check`` fetches them
again and fails unless the committed files equal the releases' bytes. Nothing comes from
a CDN; the page loads no URL.
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
# package -> version, the tarball's npm integrity, {file in the tarball: vendored name}
PINS = {
    "three": (
        "0.159.0",
        "sha512-eCmhlLGbBgucuo4VEA9IO3Qpc7dh8Bd4VKzr7WfW4+8hMcIfoAVi1ev0pJYN9P"
        "TTsCslbcKgBwr2"
        "wNZ1EvLInA==",
        {
            "package/build/three.module.min.js": "three.module.min.js",
            "package/LICENSE": "three.LICENSE",
        },
    ),
    # a 3 kB inflater: three.js travels deflated in the page (a third of its size)
    "tiny-inflate": (
        "1.0.3",
        "sha512-pkY1fj1cKHb2seWDy0B16HeWyczlJA9/WW3u3c4z/NiWDsO3DOU5D7nhTLE9CF0y"
        "Xv/QZFY7sEJm"
        "j24dK+Rrqw==",
        {
            "package/index.js": "tiny-inflate.js",
            "package/LICENSE": "tiny-inflate.LICENSE",
        },
    ),
}


def fetch_tarball(package, folder):
    """The pinned release's tarball (path), fetched by ``npm pack``, its sha512
    checked."""
    version, integrity, _ = PINS[package]
    spec = f"{package}@{version}"
    subprocess.run(
        ["npm", "pack", spec, "--silent", "--pack-destination", str(folder)],
        check=True,
        stdout=subprocess.DEVNULL,
        timeout=600,
    )
    path = pathlib.Path(folder) / f"{package}-{version}.tgz"
    got = (
        "sha512-"
        + base64.b64encode(hashlib.sha512(path.read_bytes()).digest()).decode()
    )
    if got != integrity:
        sys.exit(f"{spec}: the tarball's integrity is {got}, the pin says {integrity}")
    return path


def release_files():
    """{package: {vendored name: bytes}} of the pinned releases."""
    found = {}
    with tempfile.TemporaryDirectory() as folder:
        for package, (_, _, files) in PINS.items():
            with tarfile.open(fetch_tarball(package, folder)) as archive:
                found[package] = {
                    name: archive.extractfile(member).read()
                    for member, name in files.items()
                }
    return found


def manifest(found):
    return {
        package: {
            "version": PINS[package][0],
            "integrity": PINS[package][1],
            "sha256": {
                name: hashlib.sha256(data).hexdigest() for name, data in files.items()
            },
        }
        for package, files in found.items()
    }


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument(
        "--check",
        action="store_true",
        help="fail unless the committed files equal the pinned releases'",
    )
    args = parser.parse_args()
    found = release_files()
    files = {name: data for package in found.values() for name, data in package.items()}
    if args.check:
        wrong = [
            name
            for name, data in files.items()
            if not (VENDOR / name).is_file() or (VENDOR / name).read_bytes() != data
        ]
        if json.loads((VENDOR / "vendor.json").read_text()) != manifest(found):
            wrong.append("vendor.json")
        if wrong:
            sys.exit(
                f"screwkit/static/vendor/: {wrong} differ from the pinned npm releases "
                "(run tools/vendor_js.py)"
            )
        print(
            "screwkit/static/vendor/ equals the pinned npm releases: "
            + ", ".join(f"{p}@{PINS[p][0]}" for p in PINS)
        )
        return
    VENDOR.mkdir(parents=True, exist_ok=True)
    for name, data in files.items():
        (VENDOR / name).write_bytes(data)
    (VENDOR / "vendor.json").write_text(json.dumps(manifest(found), indent=2) + "\n")
    print("vendored " + ", ".join(f"{p}@{PINS[p][0]}" for p in PINS))


if __name__ == "__main__":
    main()
