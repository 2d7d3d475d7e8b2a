"""Shared fixtures: the repository root and the `rcagd` CLI to compare against."""

import json
import os
import pathlib
import shutil
import subprocess

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[3]


def _cli():
    env = os.environ.get("RCAGD_CLI")
    if env:
        return env if os.path.isfile(env) else None
    for p in (ROOT / "target" / "debug" / "rcagd", ROOT / "target" / "release" / "rcagd"):
        if p.is_file():
            return str(p)
    return shutil.which("rcagd")


@pytest.fixture(scope="session")
def root():
    return ROOT


@pytest.fixture(scope="session")
def cli_build():
    """`rcagd build FILE` (JSON on stdout) as a dict from object name to its JSON."""
    cli = _cli()
    if cli is None:
        pytest.skip(
            "the rcagd CLI was not found (set RCAGD_CLI or build it: cargo build -p rcagd-cli)"
        )

    def run(path):
        out = subprocess.run([cli, "build", str(path)], capture_output=True, check=False)
        assert out.returncode == 0, out.stderr.decode()
        return {o["name"]: o for o in json.loads(out.stdout)["objects"]}

    return run
