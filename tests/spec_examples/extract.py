#!/usr/bin/env python3
"""Extract the code examples of the library specs into compilable Ada units.

An example is a block of comment lines indented by at least five spaces
after "--" that follows a comment line ending with "Example:", e.g.

    --  Example:
    --     Node : Nodes.Node := Nodes.Init ("talker");
    --     Node.Spin;

Each block becomes the body of a nested package (library level): its
declarations go in the declarative part, its statements after "begin"; a declaration that follows a
statement opens a nested "declare" block, so the example reads as written.
Lines made only of "..." mark elided code and are dropped; leading
"with" lines are context clauses. The names an
example uses without declaring them come from contexts/_common.ada and
contexts/<spec file name without .ads>.ada (default: "with UNIT; use
UNIT;"): in each, the lines up to "--  DECLARATIONS" are context clauses,
the rest declarations (comment lines are dropped).

    extract.py OUT_DIR SPEC.ads...   writes OUT_DIR/spec_example_*.ad[sb] and
                                     OUT_DIR/examples.txt: per unit, its file
                                     name, SPEC:LINE of the example and the
                                     map UNIT_LINE=SPEC_LINE,...
"""
import os
import re
import sys

CONTEXTS = os.path.join(os.path.dirname(os.path.abspath(__file__)), "contexts")
MARKER = re.compile(r"^\s*--.*\bExample:\s*$")
CODE = re.compile(r"^(\s*)--     (.*)$")
EMPTY_COMMENT = re.compile(r"^\s*--\s*$")
DECLARATION = re.compile(
    r"^((overriding|not\s+overriding)\s+)?"
    r"(procedure|function|package|type|subtype|task|protected|generic|use|pragma)\b"
    r"|^[A-Za-z]\w*(\s*,\s*[A-Za-z]\w*)*\s*:(?!=)",
    re.IGNORECASE)
CONTINUES_CHUNK = re.compile(
    r"^(begin\b|end\b|else\b|elsif\b|exception\b|when\b|private\b|--|\)|and\b|or\b|&)",
    re.IGNORECASE)


class Example:
    def __init__(self, spec, line, lines):
        self.spec, self.line, self.lines = spec, line, lines


def code_blocks(text):
    """Every code block of the lines TEXT (comment lines indented five
    spaces after "--", with the empty comment lines between them) as
    (first line number, marked as an example, [(line number, code)])."""
    blocks = []
    i = 0
    while i < len(text):
        if CODE.match(text[i]):
            start, body = i, []
            while i < len(text):
                m = CODE.match(text[i])
                if m:
                    body.append((i + 1, m.group(2)))
                elif (EMPTY_COMMENT.match(text[i]) and i + 1 < len(text)
                      and CODE.match(text[i + 1])):
                    body.append((i + 1, ""))
                else:
                    break
                i += 1
            blocks.append((start + 1, start > 0 and bool(MARKER.match(text[start - 1])), body))
        else:
            i += 1
    return blocks


def find_examples(spec):
    """Every marked block of SPEC as an Example (line numbers 1-based)."""
    with open(spec, encoding="utf-8") as f:
        text = f.read().split("\n")
    return [Example(spec, first, body) for first, marked, body in code_blocks(text) if marked]


def chunks(lines):
    """Split example lines into (is_declaration, [lines]) items: a new item
    starts at each line at the block's base indentation that does not
    continue the previous one (end, begin, else, ...)."""
    items = []
    for number, line in lines:
        if line.strip() in ("", "..."):
            continue
        stripped = line.lstrip()
        base = len(line) - len(stripped) == 0
        if base and not (items and CONTINUES_CHUNK.match(stripped)):
            items.append((bool(DECLARATION.match(stripped)), [(number, line)]))
        else:
            if not items:
                items.append((False, []))
            items[-1][1].append((number, line))
    return items


def read_context_file(path):
    """(context clauses, declarations) of a context file."""
    clauses, declarations = [], []
    with open(path, encoding="utf-8") as f:
        target = clauses
        for line in f.read().split("\n"):
            if line.strip() == "--  DECLARATIONS":
                target = declarations
            elif line.strip() and not line.startswith("--"):
                target.append(line)
    return clauses, declarations


def read_context(spec):
    """The common context then the spec's own (or "with UNIT; use UNIT;")."""
    clauses, declarations = read_context_file(os.path.join(CONTEXTS, "_common.ada"))
    name = os.path.basename(spec)[:-len(".ads")]
    path = os.path.join(CONTEXTS, name + ".ada")
    if os.path.exists(path):
        own_clauses, own_declarations = read_context_file(path)
    else:
        unit = name.replace("-", ".")
        own_clauses, own_declarations = ["with %s; use %s;" % (unit, unit)], []
    return clauses + own_clauses, declarations + own_declarations


def unit_text(example, unit):
    """The body of library package UNIT: the context's declarations, then a
    package Example made of the example's lines (its names hide the
    context's; its subprograms are at library level, so 'Access works as
    in a program)."""
    clauses, context_declarations = read_context(example.spec)
    out = ["pragma Warnings (Off);"]
    out += clauses
    out.append("package body %s is" % unit)
    out += ["   " + d for d in context_declarations]
    out.append("   --  %s:%d" % (example.spec, example.line))
    out.append("   package Example is")
    out.append("   end Example;")
    out.append("   package body Example is")
    opened = 0
    in_statements = False
    items = chunks(example.lines)
    while items and items[0][1][0][1].lstrip().lower().startswith("with "):
        out.insert(1 + len(clauses), items.pop(0)[1][0][1].strip())
    origin = {}
    for is_declaration, lines in items:
        if is_declaration and in_statements:
            out.append("   declare")
            opened += 1
            in_statements = False
        elif not is_declaration and not in_statements:
            out.append("   begin")
            in_statements = True
        for number, line in lines:
            out.append("      " + line)
            origin[len(out)] = number
    if not in_statements:
        out.append("   begin")
        out.append("      null;")
    for _ in range(opened):
        out.append("   end;")
    out.append("   end Example;")
    out.append("end %s;" % unit)
    return "\n".join(out) + "\n", origin


def private_parent(spec):
    """The parent unit's name when SPEC is a private child ("RCL.MCAP" for
    "private package RCL.MCAP.Buffers"): its examples are then compiled as
    private siblings, the only units that may use it."""
    with open(spec, encoding="utf-8") as f:
        m = re.search(r"^private\s+package\s+([\w.]+)\.\w+\s+is",
                      f.read(), re.MULTILINE | re.IGNORECASE)
    return m.group(1) if m else None


def main(argv):
    if len(argv) < 3:
        print(__doc__.strip().split("\n\n")[-1], file=sys.stderr)
        return 2
    out_dir = argv[1]
    os.makedirs(out_dir, exist_ok=True)
    for old in os.listdir(out_dir):
        if old.startswith("spec_example_"):
            os.remove(os.path.join(out_dir, old))
    index = []
    for spec in argv[2:]:
        stem = re.sub(r"\W", "_", os.path.basename(spec)[:-len(".ads")])
        parent = private_parent(spec)
        for n, example in enumerate(find_examples(spec), start=1):
            unit = "Spec_Example_%s_%d" % (stem, n)
            if parent:
                unit = parent + "." + unit
            file_name = unit.lower().replace(".", "-")
            with open(os.path.join(out_dir, file_name + ".ads"), "w",
                      encoding="utf-8") as f:
                f.write("%spackage %s with Elaborate_Body is\nend %s;\n"
                        % ("private " if parent else "", unit, unit))
            with open(os.path.join(out_dir, file_name + ".adb"), "w",
                      encoding="utf-8") as f:
                text, origin = unit_text(example, unit)
                f.write(text)
            index.append("%s %s:%d %s" % (file_name, spec, example.line, ",".join(
                "%d=%d" % (unit_line, spec_line)
                for unit_line, spec_line in sorted(origin.items()))))
    with open(os.path.join(out_dir, "examples.txt"), "w", encoding="utf-8") as f:
        f.write("\n".join(index) + "\n")
    print("%d examples from %d specs" % (len(index), len(argv) - 2))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
