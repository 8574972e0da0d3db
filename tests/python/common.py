"""Shared by the module's tests: where the command, the scenes and the outputs are."""
import os
import shutil
import subprocess

SOURCE = os.environ.get("FSI_SOURCE_DIR",
                        os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))))
COMMAND = os.environ.get("FSI_COMMAND", os.path.join(SOURCE, "build", "apps", "fsi"))
OUT = os.environ.get("FSI_TEST_OUT", os.path.join(SOURCE, "build", "tests", "python", "out"))
SCENES = os.path.join(SOURCE, "data", "scenes")


def fresh(name):
    """An empty output folder OUT/name."""
    path = os.path.join(OUT, name)
    shutil.rmtree(path, ignore_errors=True)
    os.makedirs(OUT, exist_ok=True)
    return path


def command(*args):
    """`fsi ARGS...`: (exit status, stdout, stderr)."""
    p = subprocess.run([COMMAND, *args], capture_output=True, text=True)
    return p.returncode, p.stdout, p.stderr


def read_bytes(path):
    with open(path, "rb") as f:
        return f.read()
