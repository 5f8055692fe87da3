"""Shared by the example scripts: the output folder and saving (dpi 100)."""

import argparse
from pathlib import Path

import matplotlib

matplotlib.use("Agg")

#: The current directory: the scripts never write into the repository unless asked
#: (``--out doc/figures`` regenerates the figures of the docs).
DEFAULT_OUT = Path.cwd()


def output_dir(description: str) -> Path:
    parser = argparse.ArgumentParser(description=description)
    parser.add_argument("--out", type=Path, default=DEFAULT_OUT,
                        help=f"folder for the PNG files (default: {DEFAULT_OUT})")
    out = parser.parse_args().out
    out.mkdir(parents=True, exist_ok=True)
    return out


def save(fig, path: Path) -> None:
    fig.savefig(path, dpi=100)
    print(f"wrote {path} ({path.stat().st_size // 1024} KiB)")
