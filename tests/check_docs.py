#!/usr/bin/env python3
"""The documentation's links and commands are the repository's (docs/testing.md).

Usage: check_docs.py SOURCE_DIR VSGL_BENCH [VSGL_GBENCH VSGL_MIPBENCH]

Over README.md, docs/*.md and the READMEs and reports under results/:
  - every relative link and image resolves to a file or folder of the checkout, and every anchor
    (#section) to a heading (GitHub's slugs) or an id of the file it points to;
  - every repository path the text names in inline code (`ci/test.sh`, `harness/vk/...`) exists
    (a path with a placeholder such as <device> or NAME is skipped; * is a glob);
  - every `bash ci/SCRIPT` names an existing script;
  - every vsgl-bench command shown, in a code block or in inline code, names a command the built
    vsgl-bench lists in its --help and only options that command's --help lists; likewise the
    --vsgl_ and --benchmark_ options of vsgl-gbench and vsgl-mipbench, when they are given.
Prints each problem as FILE:LINE: what; exits 1 when there is any, 0 otherwise.
"""
import glob
import os
import re
import subprocess
import sys

HELP_TIMEOUT_S = 60
# Top-level folders of the checkout whose paths the docs name.
REPO_DIRS = ("bench", "ci", "cmake", "docs", "harness", "kernels", "results", "tests")
# Placeholders in commands and paths: <device>, NAME, DIR, {1,2}, …
PLACEHOLDER = re.compile(r"[<>{}…]|\.\.\.|(^|/)[A-Z][A-Z0-9_]*(/|$|\.)")


def documents(root):
    files = [os.path.join(root, "README.md")]
    files += sorted(glob.glob(os.path.join(root, "docs", "*.md")))
    for name in ("README.md", "REPORT.md"):
        files += sorted(glob.glob(os.path.join(root, "results", "**", name), recursive=True))
    return files


class Document:
    """A markdown file split into fenced code lines and prose lines, with its anchors."""

    def __init__(self, path):
        self.path = path
        self.code = []   # (line number, text) inside ``` fences, continuation lines joined
        self.prose = []  # (line number, text) outside them
        self.anchors = set()
        fence = None
        pending = None
        slugs = {}
        with open(path, encoding="utf-8") as f:
            for number, line in enumerate(f.read().split("\n"), 1):
                marker = re.match(r"^\s*(```+|~~~+)", line)
                if marker:
                    if fence is None:
                        fence = marker.group(1)
                    elif line.strip().startswith(fence):
                        fence = None
                    continue
                if fence is not None:
                    if pending:
                        pending = (pending[0], pending[1] + " " + line.strip())
                    else:
                        pending = (number, line)
                    if pending[1].endswith("\\"):
                        pending = (pending[0], pending[1][:-1])
                    else:
                        self.code.append(pending)
                        pending = None
                    continue
                self.prose.append((number, line))
                heading = re.match(r"^#{1,6}\s+(.*?)\s*#*\s*$", line)
                if heading:
                    slug = github_slug(heading.group(1))
                    n = slugs.get(slug, 0)
                    slugs[slug] = n + 1
                    self.anchors.add(slug if n == 0 else "%s-%d" % (slug, n))
                for m in re.finditer(r"""\b(?:id|name)=["']([^"']+)["']""", line):
                    self.anchors.add(m.group(1))


def github_slug(heading):
    text = re.sub(r"\[([^\]]*)\]\([^)]*\)", r"\1", heading)  # a link: its text
    text = text.strip().lower().replace("`", "")
    text = re.sub(r"[^\w\- ]", "", text)  # punctuation goes; letters, digits, _ and - stay
    return text.replace(" ", "-")


def without_code_spans(text):
    return re.sub(r"`[^`]*`", "", text)


def code_spans(text):
    return re.findall(r"`([^`]+)`", text)


class Checker:
    def __init__(self, root, programs):
        self.root = os.path.realpath(root)
        self.programs = programs  # {"vsgl-bench": Program, ...}
        self.problems = []
        self.cache = {}
        self.counts = {"links": 0, "anchors": 0, "paths": 0, "scripts": 0, "commands": 0}

    def problem(self, doc, number, what):
        self.problems.append("%s:%d: %s" % (os.path.relpath(doc.path, self.root), number, what))

    def document(self, path):
        path = os.path.realpath(path)
        if path not in self.cache:
            self.cache[path] = Document(path)
        return self.cache[path]

    # ---- links -------------------------------------------------------------------------------
    def links(self, doc):
        for number, line in doc.prose:
            text = without_code_spans(line)
            targets = [m.group(1) for m in re.finditer(r"!?\[[^\]]*\]\(\s*<?([^)\s>]+)>?(?:\s+\"[^\"]*\")?\s*\)", text)]
            targets += [m.group(1) for m in re.finditer(r"^\s*\[[^\]]+\]:\s*(\S+)", text)]
            for target in targets:
                if re.match(r"^[a-zA-Z][a-zA-Z0-9+.-]*:", target):  # https:, mailto:
                    continue
                self.link(doc, number, target)

    def link(self, doc, number, target):
        self.counts["links"] += 1
        path, _, anchor = target.partition("#")
        file = os.path.realpath(os.path.join(os.path.dirname(doc.path), path)) if path else doc.path
        if not (file == self.root or file.startswith(self.root + os.sep)):
            self.problem(doc, number, "link %s leaves the repository" % target)
            return
        if not os.path.exists(file):
            self.problem(doc, number, "link %s: %s does not exist" % (target, os.path.relpath(file, self.root)))
            return
        if anchor:
            self.counts["anchors"] += 1
            if not file.endswith(".md"):
                self.problem(doc, number, "link %s: an anchor into a file that is not markdown" % target)
            elif anchor not in self.document(file).anchors:
                self.problem(doc, number, "link %s: %s has no heading #%s" % (target, os.path.relpath(file, self.root), anchor))

    # ---- paths and scripts -------------------------------------------------------------------
    def paths(self, doc):
        # Inline code only: a code block's paths are as often what a command writes (--out results/mine).
        spans = [(n, s) for n, line in doc.prose for s in code_spans(line)]
        for number, text in spans:
            for m in re.finditer(r"(?<![\w./-])((?:%s)/[\w./*<>{}…,-]*)" % "|".join(REPO_DIRS), text):
                path = m.group(1).rstrip(".,")
                if PLACEHOLDER.search(path) or "," in path:
                    continue
                self.counts["paths"] += 1
                # A program may be named by its source's stem (tests/fuzz/measure_check_file).
                if not glob.glob(os.path.join(self.root, path)) and not glob.glob(os.path.join(self.root, path + ".*")):
                    self.problem(doc, number, "%s does not exist in the repository" % path)
        for number, line in doc.prose + doc.code:
            for m in re.finditer(r"\bbash\s+(ci/[\w./-]*\w)", line):
                script = m.group(1)
                self.counts["scripts"] += 1
                if not os.path.isfile(os.path.join(self.root, script)):
                    self.problem(doc, number, "bash %s: no such script" % script)

    # ---- commands ----------------------------------------------------------------------------
    def commands(self, doc):
        texts = [(n, s) for n, line in doc.prose for s in code_spans(line)]
        texts += [(n, re.sub(r"(^|\s)#.*$", "", line)) for n, line in doc.code]  # shell comments go
        for number, text in texts:
            text = text.replace("\\|", "|")  # an alternative in a table cell: gab\|bmf
            for name, program in self.programs.items():
                for m in re.finditer(r"(?<![\w.-])%s(?![\w./-])([^;&|()`]*)" % re.escape(name), text):
                    self.counts["commands"] += 1
                    for what in program.check(m.group(1).split()):
                        self.problem(doc, number, "%s%s: %s" % (name, m.group(1).rstrip(), what))

    def run(self):
        for path in documents(self.root):
            doc = self.document(path)
            self.links(doc)
            self.paths(doc)
            self.commands(doc)
        return self.problems


def help_text(program, args):
    r = subprocess.run([program] + args + ["--help"], stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                       timeout=HELP_TIMEOUT_S, env=dict(os.environ, VK_ICD_FILENAMES="/nonexistent"))
    if r.returncode != 0:
        raise RuntimeError("%s %s --help exited %d:\n%s" % (program, " ".join(args), r.returncode, r.stdout.decode()))
    return r.stdout.decode("utf-8", "replace")


def option_names(help):
    """The options a CLI11 help lists: the first column of its option lines (-h,--help ...)."""
    names = set()
    for line in help.split("\n"):
        m = re.match(r"^\s+((?:--?[A-Za-z0-9][\w-]*,?)+)", line)
        if m:
            names.update(n for n in m.group(1).split(",") if n)
    return names


class BenchProgram:
    """vsgl-bench: its commands from the top-level help, each command's options from its own."""

    def __init__(self, exe):
        self.exe = exe
        top = help_text(exe, [])
        section = re.search(r"^(?:Sub)?[Cc]ommands:\n((?:  .*\n)+)", top, re.M)
        if not section:
            raise RuntimeError("vsgl-bench --help lists no commands:\n" + top)
        self.commands = set(re.findall(r"^  ([a-z][\w-]*)", section.group(1), re.M))
        self.top_options = option_names(top.split("Commands:")[0])
        self.options = {}

    def command_options(self, command):
        if command not in self.options:
            self.options[command] = option_names(help_text(self.exe, [command]))
        return self.options[command]

    def check(self, tokens):
        if not tokens:
            return []
        if tokens[0].startswith("-"):
            command, options, rest = "", self.top_options, tokens
        elif PLACEHOLDER.search(tokens[0]):
            return []  # vsgl-bench <command> --help
        elif tokens[0] == "help":
            return []  # `vsgl-bench help` is the top-level help
        elif tokens[0] not in self.commands:
            return ["no command '%s' (vsgl-bench --help lists %s)" % (tokens[0], ", ".join(sorted(self.commands)))]
        else:
            command, options, rest = tokens[0], self.command_options(tokens[0]), tokens[1:]
        problems = []
        for t in rest:
            name = t.strip("[]").split("=", 1)[0]  # [--json]: an optional option
            if re.match(r"^--?[A-Za-z]", name) and name not in options:
                problems.append("no option %s in vsgl-bench %s--help" % (name, command + " " if command else ""))
        return problems


class BenchmarkProgram:
    """vsgl-gbench, vsgl-mipbench: their --vsgl_ options and Google Benchmark's --benchmark_ ones."""

    def __init__(self, exe):
        help = help_text(exe, [])
        self.options = set(re.findall(r"(?<![\w-])(--[A-Za-z][\w-]*)", help))

    def check(self, tokens):
        names = [t.strip("[]").split("=", 1)[0] for t in tokens]
        return ["no option %s in its --help" % n for n in names if n.startswith("--") and n not in self.options]


def main(argv):
    if len(argv) not in (3, 5):
        print(__doc__.split("\n")[2], file=sys.stderr)
        return 2
    programs = {"vsgl-bench": BenchProgram(argv[2])}
    if len(argv) == 5 and argv[3] != "-":
        programs["vsgl-gbench"] = BenchmarkProgram(argv[3])
        programs["vsgl-mipbench"] = BenchmarkProgram(argv[4])
    checker = Checker(argv[1], programs)
    problems = checker.run()
    for p in problems:
        print(p)
    c = checker.counts
    print("%d documents: %d links (%d anchors), %d paths, %d scripts, %d commands checked; %d problems" %
          (len(documents(argv[1])), c["links"], c["anchors"], c["paths"], c["scripts"], c["commands"], len(problems)))
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
