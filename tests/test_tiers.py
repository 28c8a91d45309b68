"""`make test` (--tier fast) and the slow tiers (--tier slow) together are every test
(`make test-all`, --tier all), with none in both: splitting the suite loses no test.
A slow check itself (three collections of the whole suite): in the slow tier."""

import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]


def collected(tier):
    result = subprocess.run(
        [sys.executable, "-m", "pytest", "tests", "screwkit", "--doctest-modules"]
        + ["--collect-only", "-q", "-p", "no:cacheprovider", "--tier", tier],
        cwd=ROOT,
        capture_output=True,
        text=True,
        timeout=900,
    )
    assert result.returncode == 0, result.stdout[-2000:] + result.stderr[-2000:]
    return [line for line in result.stdout.splitlines() if "::" in line]


def test_the_fast_and_the_slow_tiers_are_every_test_once():
    every, fast, slow = collected("all"), collected("fast"), collected("slow")
    assert len(set(every)) == len(every) > 2000
    assert not set(fast) & set(slow)
    assert sorted(fast + slow) == sorted(every)
    assert (
        len(slow) >= 30
        and "tests/test_tiers.py::"
        + ("test_the_fast_and_the_slow_tiers_are_every_test_once")
        in slow
    )
