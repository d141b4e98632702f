#!/usr/bin/python3
"""Runs every command the documentation shows, as an engineer would on a first day.

From README.md, docs/tutorial.md and docs/library.md: every fenced block marked sh, bash or console (shell
commands, one a line, `\\` continuing a line) and every block marked python (run with
/usr/bin/python3 where it stands, after the commands above it have written its files). From the
help texts: the lines under "Examples:" of `flexmoor --help` and of each command's `--help`.

Everything runs in one scratch working directory laid out as the source tree is (cases/,
scripts/, apps/ and build/ as links), in the order the documents are read: README.md, then
docs/tutorial.md, then the help texts, so results land in the scratch directory and a study run
again into the same DIR resumes, as the README says. `flexmoor` is the built command (build/bin
first on PATH). A command must exit 0, unless the document shows it failing on purpose with a
comment `# exit N: ...` after it: then it must exit N. After a command that exits 0, the path
it names with `-o` must exist.

A command is left out only by a visible marker in the document, a comment on its line or on
the comment line just above it: `# not run by the docs test: REASON`. An unmarked command that
installs packages, needs root or runs the benchmarks or the whole suite fails the test instead
of running. A fenced block without a language whose lines look like commands fails it too:
blocks meant to be run say sh.

Prints, per document, the commands run, the Python snippets run and the commands left out (with
their reasons); exit status 1 when any command failed.

Usage: run_doc_commands.py SOURCE_DIR BUILD_DIR [--mpi ON|OFF] [--keep]
"""

import argparse
import os
import re
import shlex
import shutil
import subprocess
import sys
import tempfile
import time

SKIP_MARK = "not run by the docs test"
EXIT_MARK = re.compile(r"^#\s*exit (\d+)\b")
# Commands that must never run unmarked: they install packages, need root or take many minutes.
HEAVY = re.compile(r"(^|[\s/])(apt-get|apt|sudo|setup\.sh|quickstart\.sh|test\.sh|fuzz\.sh|"
                   r"bench[a-z_]*\.sh|study_speedup\.sh|surge_convergence\.sh|bench_output\.sh)\b")
LOOKS_LIKE_COMMAND = re.compile(r"^\s*(build/bin/flexmoor|flexmoor|bash |mpirun |ncdump |"
                                r"python3? |/usr/bin/python3 )")
SHELL_LANGS = {"sh", "bash", "console", "shell"}
PYTHON_LANGS = {"python", "py"}
COMMAND_TIMEOUT = 600


class Item:
    """One command or snippet of a document."""

    def __init__(self, kind, text, line, expect=0, skip=None):
        self.kind = kind  # "shell" or "python"
        self.text = text
        self.line = line  # where it stands: "README.md:123" or "flexmoor run --help"
        self.expect = expect
        self.skip = skip


def comment_of(line):
    """(command, comment) of a shell line: the comment starts at an unquoted '#' after a blank."""
    quote = None
    for i, ch in enumerate(line):
        if quote:
            if ch == quote:
                quote = None
        elif ch in "'\"":
            quote = ch
        elif ch == "#" and (i == 0 or line[i - 1].isspace()):
            return line[:i].rstrip(), line[i:]
    return line.rstrip(), ""


def shell_items(lines, where):
    """The commands of a shell block; `lines` are (line number or label, text)."""
    items = []
    pending_comment = ""  # a comment line just above a command
    i = 0
    while i < len(lines):
        label, text = lines[i]
        if text.startswith("$ "):  # a console block's prompt
            text = text[2:]
        stripped = text.strip()
        if not stripped:
            pending_comment = ""
            i += 1
            continue
        if stripped.startswith("#"):
            pending_comment = stripped
            i += 1
            continue
        parts, comments = [], []
        while True:
            command, comment = comment_of(text.strip())
            if comment:
                comments.append(comment)
            if command.endswith("\\") and i + 1 < len(lines):
                parts.append(command[:-1].rstrip())
                i += 1
                text = lines[i][1]
                continue
            parts.append(command)
            break
        i += 1
        command = " ".join(p for p in parts if p)
        expect, skip = 0, None
        for comment in [pending_comment] + comments:
            if SKIP_MARK in comment:
                skip = comment.split(SKIP_MARK, 1)[1].lstrip(" :") or "(no reason given)"
        for comment in comments:
            m = EXIT_MARK.match(comment)
            if m:
                expect = int(m.group(1))
        pending_comment = ""
        items.append(Item("shell", command, where(label), expect, skip))
    return items


def markdown_items(path, name, problems):
    """The shell commands and Python snippets of a Markdown file's fenced blocks, in order."""
    with open(path, encoding="utf-8") as f:
        lines = f.read().split("\n")
    items = []
    i = 0
    fence = re.compile(r"^(\s*)(```+)\s*([\w+-]*)\s*$")
    while i < len(lines):
        m = fence.match(lines[i])
        if not m:
            i += 1
            continue
        indent, ticks, lang = len(m.group(1)), m.group(2), m.group(3).lower()
        start = i + 1
        j = start
        while j < len(lines) and lines[j].strip() != ticks:
            j += 1
        # The block's lines less the fence's indentation (a Python block keeps its own).
        body = [(k + 1, lines[k][indent:] if not lines[k][:indent].strip() else lines[k].lstrip())
                for k in range(start, min(j, len(lines)))]
        where = lambda n: f"{name}:{n}"  # noqa: E731
        if lang in SHELL_LANGS:
            items += shell_items(body, where)
        elif lang in PYTHON_LANGS:
            items.append(Item("python", "\n".join(t for _, t in body), where(start)))
        elif lang in ("", "text"):
            for n, t in body:
                if LOOKS_LIKE_COMMAND.match(t):
                    problems.append(f"{name}:{n}: a command in a block not marked sh "
                                    f"(mark blocks meant to be run ```sh): {t.strip()}")
        i = j + 1
    return items


def help_text(binary, command):
    args = [binary] + ([command] if command else []) + ["--help"]
    return subprocess.run(args, capture_output=True, text=True, check=True).stdout


def help_items(binary, problems):
    """(label, items) per help text: the top-level one, then each command's."""
    top = help_text(binary, None)
    commands = []
    in_list = False
    for line in top.split("\n"):
        if line.strip().lower() == "subcommands:":
            in_list = True
            continue
        if in_list:
            if not line.strip():
                break
            commands.append(line.split()[0])
    if not commands:
        problems.append("flexmoor --help: no list of commands found")
    docs = []
    for command in [None] + commands:
        label = "flexmoor " + (command + " " if command else "") + "--help"
        text = top if command is None else help_text(binary, command)
        lines = text.split("\n")
        body = []
        for k, line in enumerate(lines):
            if line.strip() == "Examples:":
                for n in range(k + 1, len(lines)):
                    if not lines[n].strip():
                        break
                    body.append((f"{label}, example line {n - k}", lines[n]))
                break
        docs.append((label, shell_items(body, lambda where: where)))
    return docs


def make_workdir(source, build):
    work = tempfile.mkdtemp(prefix="flexmoor-docs-")
    for name in ("cases", "scripts", "apps", "tests", "examples"):
        os.symlink(os.path.join(source, name), os.path.join(work, name))
    os.symlink(build, os.path.join(work, "build"))
    return work


def output_path(command):
    """The path a command names with -o (relative to the working directory), if any."""
    try:
        words = shlex.split(command)
    except ValueError:
        return None
    for k, w in enumerate(words[:-1]):
        if w in ("-o", "--output"):
            return words[k + 1]
    return None


def run_item(item, work, env, log):
    start = time.monotonic()
    if item.kind == "shell":
        args = ["/bin/bash", "-c", item.text]
    else:
        args = ["/usr/bin/python3", "-c", item.text]
    try:
        r = subprocess.run(args, cwd=work, env=env, capture_output=True, text=True,
                           timeout=COMMAND_TIMEOUT, stdin=subprocess.DEVNULL)
        code, out, err = r.returncode, r.stdout, r.stderr
    except subprocess.TimeoutExpired as e:
        code, out, err = "timeout", str(e.stdout or ""), str(e.stderr or "")
    seconds = time.monotonic() - start
    log.write(f"### {item.line} ({seconds:.1f} s, exit {code})\n{item.text}\n"
              f"--- stdout\n{out}\n--- stderr\n{err}\n")
    failure = None
    if code != item.expect:
        failure = f"exit {code}, expected {item.expect}"
    elif item.kind == "shell" and code == 0:
        out_path = output_path(item.text)
        if out_path and not os.path.exists(os.path.join(work, out_path)):
            failure = f"exit 0 but its output {out_path} is not there"
    if failure:
        tail = lambda s: "\n".join(s.rstrip().split("\n")[-15:])  # noqa: E731
        print(f"FAILED {item.line}: {failure}\n  {item.text}\n--- stdout (end)\n{tail(out)}\n"
              f"--- stderr (end)\n{tail(err)}\n", flush=True)
    return failure is None, seconds


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("source")
    parser.add_argument("build")
    parser.add_argument("--mpi", default="ON")
    parser.add_argument("--keep", action="store_true", help="keep the working directory")
    a = parser.parse_args()
    source, build = os.path.realpath(a.source), os.path.realpath(a.build)
    binary = os.path.join(build, "bin", "flexmoor")
    mpi = a.mpi.upper() in ("ON", "1", "TRUE", "YES")

    problems = []
    documents = [(name, markdown_items(os.path.join(source, name), name, problems))
                 for name in ("README.md", "docs/tutorial.md", "docs/library.md")]
    documents += help_items(binary, problems)
    for p in problems:
        print(f"FAILED {p}")

    work = make_workdir(source, build)
    env = dict(os.environ)
    env["PATH"] = os.path.join(build, "bin") + os.pathsep + env.get("PATH", "")
    env["MPLBACKEND"] = "Agg"
    # The Python module where docs/library.md says it is in the build tree.
    env["PYTHONPATH"] = os.path.join(build, "python")
    if os.geteuid() == 0:  # OpenMPI's own switches for what the docs say to add as root
        env["OMPI_ALLOW_RUN_AS_ROOT"] = "1"
        env["OMPI_ALLOW_RUN_AS_ROOT_CONFIRM"] = "1"
    env["OMPI_MCA_rmaps_base_oversubscribe"] = "1"  # more ranks than cores, as the docs say
    print(f"docs test: working directory {work}", flush=True)

    failed = len(problems)
    summary = []
    notes = []
    log_path = os.path.join(work, "docs-commands.log")
    total_start = time.monotonic()
    with open(log_path, "w", encoding="utf-8") as log:
        for name, items in documents:
            ran = {"shell": 0, "python": 0}
            skipped = []
            doc_seconds = 0.0
            for item in items:
                if item.skip is None and item.kind == "shell" and HEAVY.search(item.text):
                    print(f"FAILED {item.line}: installs packages, needs root or takes minutes, "
                          f"and its document does not mark it '# {SKIP_MARK}: REASON'\n"
                          f"  {item.text}", flush=True)
                    failed += 1
                    continue
                out_path = output_path(item.text) if item.kind == "shell" else None
                if item.skip is None and out_path and (os.path.isabs(out_path) or
                                                       out_path.split("/")[0] == ".."):
                    print(f"FAILED {item.line}: writes outside the working directory "
                          f"(-o {out_path}); show a relative DIR\n  {item.text}", flush=True)
                    failed += 1
                    continue
                if item.skip is None and not mpi and item.text.startswith("mpirun "):
                    # Built without MPI: the same study, run locally, so what follows has it.
                    words = item.text.split()
                    k = next(i for i, w in enumerate(words) if w.endswith("flexmoor"))
                    item.text = " ".join(words[k:])
                    notes.append(f"{item.line}: run without mpirun (FLEXMOOR_MPI off)")
                if item.skip is not None:
                    skipped.append(item)
                    continue
                ok, seconds = run_item(item, work, env, log)
                doc_seconds += seconds
                ran[item.kind] += 1
                if not ok:
                    failed += 1
            summary.append((name, ran, skipped, doc_seconds))
    for name, ran, skipped, seconds in summary:
        plural = lambda n, word: f"{n} {word}" + ("" if n == 1 else "s")  # noqa: E731
        print(f"{name}: {plural(ran['shell'], 'command')} and "
              f"{plural(ran['python'], 'Python snippet')} run ({seconds:.0f} s), "
              f"{len(skipped)} left out", flush=True)
        for item in skipped:
            print(f"  left out {item.line}: {item.text}  ({item.skip})")
    for note in notes:
        print(f"  note {note}")
    runs = sum(r["shell"] + r["python"] for _, r, _, _ in summary)
    print(f"docs test: {runs} run in all, {failed} failed, "
          f"{time.monotonic() - total_start:.0f} s; log {log_path}")
    if failed or a.keep:
        print(f"docs test: working directory kept: {work}")
    else:
        shutil.rmtree(work, ignore_errors=True)
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
