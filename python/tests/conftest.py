"""Shared fixtures. The tests run against the *installed* package: run pytest from a
directory where `import wavyadhesion` finds site-packages (e.g. the repository root:
`pytest python/tests`), after `pip install ./python`."""

import os
from pathlib import Path

import pytest

import wavyadhesion

_HERE = Path(__file__).resolve().parent
_SOURCE_PACKAGE = _HERE.parent / "wavyadhesion"

if Path(wavyadhesion.__file__).resolve().parent == _SOURCE_PACKAGE:
    raise RuntimeError(
        "wavyadhesion was imported from the source tree, not the installed package: "
        "run pytest from outside python/ after `pip install ./python`"
    )


def repo_root():
    """The repository (for test/data and the sources), or None when not found:
    $WAVYADHESION_REPO, else two levels above this file."""
    env = os.environ.get("WAVYADHESION_REPO")
    candidates = [Path(env)] if env else []
    candidates.append(_HERE.parent.parent)
    for path in candidates:
        if (path / "fpm.toml").is_file() and (path / "src").is_dir():
            return path
    return None


@pytest.fixture(scope="session")
def repo():
    root = repo_root()
    if root is None:
        pytest.skip("repository not found (set WAVYADHESION_REPO)")
    return root
