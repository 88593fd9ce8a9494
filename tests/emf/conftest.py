"""The EMF harness: compiled once per test session with javac against Debian's Eclipse EMF jars."""

from __future__ import annotations

import os
import shutil
import subprocess
from dataclasses import dataclass
from pathlib import Path

import pytest

HERE = Path(__file__).resolve().parent
REPO = HERE.parents[1]
ECORE = REPO / "metamodel" / "scemlmodel.ecore"
JARS = ("eclipse-emf-common", "eclipse-emf-ecore", "eclipse-emf-ecore-xmi")
JAR_FOLDER = Path("/usr/share/java")


@dataclass(frozen=True)
class Harness:
    """Runs SceMLHarness modes; see tests/emf/java/SceMLHarness.java."""

    classpath: str

    def run(self, *args: str | Path, check: bool = True) -> subprocess.CompletedProcess[str]:
        """Run one mode; with `check`, a non-zero exit fails the test showing EMF's output."""
        result = subprocess.run(
            ["java", "-cp", self.classpath, "SceMLHarness", *map(str, args)],
            capture_output=True,
            text=True,
            timeout=300,
        )
        if check and result.returncode != 0:
            pytest.fail(f"EMF harness {args[0]} failed:\n{result.stdout}\n{result.stderr}")
        return result


def _unavailable(reason: str) -> None:
    # In CI the JDK and EMF are installed by scripts/setup.sh, so their absence is a failure.
    if os.environ.get("CI"):
        pytest.fail(f"EMF harness unavailable in CI: {reason}")
    pytest.skip(
        f"EMF harness unavailable: {reason} (install default-jdk-headless and "
        "libeclipse-emf-ecore-xmi-java, or run scripts/setup.sh)"
    )


@pytest.fixture(scope="session")
def emf(tmp_path_factory: pytest.TempPathFactory) -> Harness:
    """The compiled harness."""
    for tool in ("javac", "java"):
        if shutil.which(tool) is None:
            _unavailable(f"{tool} is not on PATH")
    jars = [JAR_FOLDER / f"{name}.jar" for name in JARS]
    missing = [str(jar) for jar in jars if not jar.is_file()]
    if missing:
        _unavailable(f"missing {', '.join(missing)}")
    classes = tmp_path_factory.mktemp("emf-classes")
    classpath = os.pathsep.join(str(jar) for jar in jars)
    compiled = subprocess.run(
        ["javac", "-d", str(classes), "-cp", classpath, str(HERE / "java" / "SceMLHarness.java")],
        capture_output=True,
        text=True,
        timeout=300,
    )
    if compiled.returncode != 0:
        pytest.fail(f"javac failed:\n{compiled.stderr}")
    return Harness(classpath=os.pathsep.join([str(classes), classpath]))
