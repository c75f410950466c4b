"""The pytest + Hypothesis example of docs/python.md: the page shows
examples/python/test_pure_dcel.py verbatim, it passes on the correct
pure-Python DCEL, and it fails, with a counterexample of at most 5 vertices,
on each planted bug."""
import os
import re
import subprocess
import sys

import pytest

from conftest import SOURCE_DIR

EXAMPLE = os.path.join(SOURCE_DIR, "examples", "python", "test_pure_dcel.py")
DOCS = os.path.join(SOURCE_DIR, "docs", "python.md")


def run_example(bug=""):
    env = dict(os.environ, DCEL_EXAMPLE_BUG=bug)
    return subprocess.run(
        [sys.executable, "-m", "pytest", "-q", "-p", "no:cacheprovider", "--hypothesis-seed=0", EXAMPLE],
        cwd=SOURCE_DIR, env=env, capture_output=True, text=True, timeout=600)


def test_the_docs_show_the_example_verbatim():
    with open(EXAMPLE, encoding="utf-8") as f:
        example = f.read()
    with open(DOCS, encoding="utf-8") as f:
        docs = f.read()
    blocks = re.findall(r"```python\n(.*?)```", docs, flags=re.S)
    assert example in blocks, "docs/python.md must show examples/python/test_pure_dcel.py as it is"


def test_the_sessions_on_the_page_run():
    import doctest

    result = doctest.testfile(DOCS, module_relative=False, optionflags=doctest.ELLIPSIS)
    assert result.attempted > 10 and result.failed == 0


def test_the_transcripts_on_the_page_print_what_they_show(tmp_path):
    """The page's console transcripts are marked skip for docs.examples (they need the module installed);
    here they run as scripts/check-docs runs transcripts, with this build's module as the installed one."""
    from conftest import cli_path

    text = open(DOCS, encoding="utf-8").read()
    unskipped = re.sub(r"<!-- docs-test: skip needs the module installed[^>]*-->\n", "", text)
    assert unskipped != text
    page = tmp_path / "python.md"
    page.write_text(unskipped, encoding="utf-8")
    # The page shows a developer's terminal: the default SVG folder, and
    # Hypothesis' default profile (with CI set it adds a @reproduce_failure
    # line to every failure).
    env = {k: v for k, v in os.environ.items() if k not in ("DCEL_SVG_DIR", "CI")}
    env["PATH"] = os.path.dirname(sys.executable) + os.pathsep + env.get("PATH", "")  # python3: this interpreter
    done = subprocess.run([sys.executable, os.path.join(SOURCE_DIR, "scripts", "check-docs"), "--dcel", cli_path(),
                           str(page)], env=env, capture_output=True, text=True, timeout=900)
    assert done.returncode == 0, done.stdout + done.stderr
    assert re.search(r"[1-9]\d* commands run", done.stdout), done.stdout


def test_the_example_passes():
    done = run_example()
    assert done.returncode == 0, done.stdout + done.stderr
    assert re.search(r"\b3 passed\b", done.stdout), done.stdout


@pytest.mark.parametrize("bug", ["atan2", "ccw", "isolated"])
def test_the_example_catches_each_planted_bug(bug):
    done = run_example(bug)
    assert done.returncode == 1, done.stdout + done.stderr
    assert "Falsifying example" in done.stdout
    sizes = [len(re.findall(r"\(", m)) for m in re.findall(r"vertices=\[(.*?)\]", done.stdout)]
    assert sizes and min(sizes) <= 5, done.stdout
