"""The course tests read the chapters' exercises as the tools do: with
tools/exercise_syntax.py, on the import path here."""

import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "tools"))
