"""python/README.md's examples run as written (from the repository root) and print what the README shows."""
import os
import re
import subprocess
import sys

from conftest import REPOSITORY


def examples():
    """Each python code block of the README with the output block right after it, where there is one."""
    text = (REPOSITORY / "python" / "README.md").read_text()
    return re.findall(r"```python\n(.*?)```\n```\n(.*?)```", text, flags=re.S)


def test_every_example_prints_what_the_readme_shows():
    found = examples()
    assert len(found) >= 2  # the largest empty ball, and the contact areas between residues
    for code, shown in found:
        result = subprocess.run([sys.executable, "-c", code], cwd=REPOSITORY, capture_output=True, text=True,
                                timeout=300, env=dict(os.environ))
        assert result.returncode == 0, result.stderr
        assert result.stdout == shown, code
