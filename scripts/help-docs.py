#!/usr/bin/env python3
"""Pages made from what the program says about itself, so they cannot drift from it.

    help-docs.py man         BINARY OUT   shadowlab.1
    help-docs.py completion  BINARY OUT   the bash completion
    help-docs.py cli-md      BINARY OUT   docs/cli.md
    help-docs.py settings-md BINARY OUT   docs/settings.md

Each reads `shadowlab --help`, `shadowlab help <command>` and `shadowlab settings --json`
(the settings table), run on the headless platform. The build makes the first two
(packaging/CMakeLists.txt); scripts/docs.sh the last two, which are committed.
"""

import json
import os
import re
import subprocess
import sys
from dataclasses import dataclass, field


@dataclass
class Option:
    names: list          # ["-h", "--help"]
    value: str           # "name|file", or "" for a flag
    text: str


@dataclass
class Command:
    name: str
    summary: str                         # its line in `shadowlab --help`
    usage: str = ""                      # "shadowlab render [options]"
    description: str = ""
    options: list = field(default_factory=list)


@dataclass
class Program:
    usage: list          # the synopsis lines, without "usage: "
    intro: str
    commands: list
    options: list        # of the binary itself (--help, --version)
    settings: list       # `settings --json`: key, type, range, default, help, choices
    version: str


def run(binary, *arguments):
    # Headless and untranslated, whatever the caller's display and locale.
    env = {k: v for k, v in os.environ.items() if not k.startswith("SHADOWLAB_")}
    env.update(QT_QPA_PLATFORM="headless", LC_ALL="C.UTF-8", LANG="C.UTF-8")
    env.pop("DISPLAY", None)
    env.pop("WAYLAND_DISPLAY", None)
    return subprocess.run([binary, *arguments], check=True, capture_output=True, text=True, env=env).stdout


def sections(text):
    """Qt's help text as {"Options": [entry lines...]}: a line ending in ':' at the margin heads a
    section, and a blank line ends it."""
    found, current = {}, None
    for line in text.splitlines():
        if line and not line[0].isspace() and line.endswith(":"):
            current = found.setdefault(line[:-1], [])
        elif not line.strip():
            current = None
        elif current is not None:
            current.append(line)
    return found


OPTION_NAME = r"-{1,2}[\w-]+(?: <[^>]*>)?"


def entries(lines):
    """Indented two-column entries ("  --size <WxH>   Image size ..."), wrapped lines joined."""
    result = []
    for line in lines:
        # An option's names are known by their dashes (the binary's own list has one space before
        # its text); anything else ends at two spaces.
        match = re.match(r"^  (%s(?:, %s)*)(?: +(.*))?$" % (OPTION_NAME, OPTION_NAME), line) \
            or re.match(r"^  (\S.*?)(?: {2,}(.*))?$", line)
        if match and not line.startswith("   "):
            result.append([match.group(1), match.group(2) or ""])
        elif result:
            result[-1][1] = (result[-1][1] + " " + line.strip()).strip()
    return result


def parse_option(names_text, text):
    value = ""
    names = []
    for part in names_text.split(", "):
        match = re.match(r"^(\S+)(?: <(.*)>)?$", part)
        names.append(match.group(1))
        value = match.group(2) or value
    return Option(names, value, text)


def parse_command(command, text):
    lines = text.splitlines()
    command.usage = lines[0].removeprefix("Usage: ")
    command.description = lines[1] if len(lines) > 1 and lines[1] and not lines[1].endswith(":") else ""
    command.options = [parse_option(*e) for e in entries(sections(text).get("Options", []))]
    return command


def read_program(binary):
    text = run(binary, "--help")
    lines = text.splitlines()
    usage = []
    for line in lines:
        if not line.strip():
            break
        usage.append(re.sub(r"^(usage:)?\s*", "", line))
    intro = text.split("\n\n")[1].replace("\n", " ").removesuffix(" Commands:").strip()
    found = sections(text)
    commands = [parse_command(Command(name, summary), run(binary, "help", name)) for name, summary in entries(found["Commands"])]
    options = [parse_option(*e) for e in entries(found["Options"])]
    version = run(binary, "--version").splitlines()[0].split()[-1]   # "shadowlab 0.1.0", then the licence
    return Program(usage, intro, commands, options, json.loads(run(binary, "settings", "--json")), version)


def key_group(key):
    return key.split(".")[0]


# ---- man page ---------------------------------------------------------------------------------

def roff(text):
    """Plain text as roff: backslashes and hyphens escaped (options stay copyable), `code` bold."""
    text = text.replace("\\", "\\e").replace("-", "\\-")
    text = re.sub(r"`([^`]*)`", r"\\fB\1\\fR", text)
    return "\\&" + text if text[:1] in (".", "'") else text


def roff_option(option):
    names = ", ".join("\\fB%s\\fR" % roff(n) for n in option.names)
    return names + (" \\fI%s\\fR" % roff(option.value) if option.value else "")


def man_page(program):
    out = [
        '.TH SHADOWLAB 1 "" "ShadowLab %s" "User Commands"' % program.version,
        ".SH NAME",
        "shadowlab \\- explore shadow mapping: what each setting costs and where it goes wrong",
        ".SH SYNOPSIS",
    ]
    for line in program.usage:
        out += [".br" if out[-1] != ".SH SYNOPSIS" else "", roff(line)]
    out = [line for line in out if line]
    out += [".SH DESCRIPTION", roff(program.intro), ".SH COMMANDS"]
    for c in program.commands:
        out += [".TP", "\\fB%s\\fR" % c.name, roff(c.summary)]
    out += [".SH OPTIONS"]
    for o in program.options:
        out += [".TP", roff_option(o), roff(o.text)]
    out += [".SH \"COMMAND OPTIONS\""]
    for c in program.commands:
        out += [".SS \"%s\"" % roff(c.usage), roff(c.description)]
        for o in c.options:
            out += [".TP", roff_option(o), roff(o.text)]
    out += [".SH SETTINGS",
            roff("Every command and the explorer take these keys, as --set key=value or in a --settings file. "
                 "The defaults are the seed scene's; `shadowlab settings --scene NAME` lists another scene's.")]
    for s in program.settings:
        out += [".TP", "\\fB%s\\fR (%s)" % (roff(s["key"]), roff(s["type"])),
                roff("%s Range: %s. Default: %s." % (s["help"].rstrip(".") + ".", s["range"], s["default"]))]
    out += [".SH EXIT STATUS",
            "0 when the command did what it was asked, 1 when it failed (the driver, or writing a file), "
            "2 for input it cannot take (nothing was done)."]
    return "\n".join(out) + "\n"


# ---- bash completion --------------------------------------------------------------------------

COMPLETION = r"""# bash completion for shadowlab. Generated by scripts/help-docs.py from the program's help and
# its settings table; do not edit.

_shadowlab_commands='@COMMANDS@'
_shadowlab_keys='@KEYS@'
_shadowlab_scenes='@SCENES@'
_shadowlab_presets='@PRESETS@'

# The options of a command ('' for the explorer).
_shadowlab_options()
{
    case $1 in
@OPTIONS@
    esac
}

# What a command's option takes: file, dir or value (typed); nothing for a flag.
_shadowlab_takes()
{
    case "$1 $2" in
@TAKES@
    esac
}

# The values of a choice or bool key.
_shadowlab_values()
{
    case $1 in
@VALUES@
    esac
}

# `--set key=value`: the key, then its values.
_shadowlab_assignment()
{
    local cur=$1
    if [[ $cur == *=* ]]; then
        COMPREPLY=($(compgen -P "${cur%%=*}=" -W "$(_shadowlab_values "${cur%%=*}")" -- "${cur#*=}"))
    else
        COMPREPLY=($(compgen -S = -W "$_shadowlab_keys" -- "$cur"))
        compopt -o nospace 2>/dev/null
    fi
}

_shadowlab_files()
{
    COMPREPLY+=($(compgen -f -- "$1"))
    compopt -o filenames 2>/dev/null
}

_shadowlab()
{
    # Words split at blanks only: bash also splits at '=' and ':', which `--set key=value` has.
    local line=${COMP_LINE:0:COMP_POINT} words
    read -ra words <<<"$line"
    [[ -z $line || $line == *[[:space:]] ]] && words+=('')
    local cur=${words[${#words[@]}-1]} prev=${words[${#words[@]}-2]:-} command=''
    COMPREPLY=()
    if ((${#words[@]} == 2)) && [[ $cur != -* ]]; then
        COMPREPLY=($(compgen -W "$_shadowlab_commands help" -- "$cur"))
        _shadowlab_files "$cur"
        return
    fi
    if ((${#words[@]} > 2)); then
        if [[ ${words[1]} == help ]]; then
            ((${#words[@]} == 3)) && COMPREPLY=($(compgen -W "$_shadowlab_commands" -- "$cur"))
            return
        fi
        [[ " $_shadowlab_commands " == *" ${words[1]} "* ]] && command=${words[1]}
    fi
    case $prev in
        --set | --set-b) _shadowlab_assignment "$cur" ;;
        --scene) COMPREPLY=($(compgen -W "$_shadowlab_scenes" -- "$cur")); _shadowlab_files "$cur" ;;
        --preset) COMPREPLY=($(compgen -W "$_shadowlab_presets" -- "$cur")) ;;
        *)
            case $(_shadowlab_takes "$command" "$prev") in
                file) _shadowlab_files "$cur" ;;
                dir) COMPREPLY=($(compgen -d -- "$cur")); compopt -o filenames 2>/dev/null ;;
                value) ;;
                *)
                    if [[ $cur == -* ]]; then
                        COMPREPLY=($(compgen -W "$(_shadowlab_options "$command")" -- "$cur"))
                    elif [[ -z $command ]]; then
                        _shadowlab_files "$cur"   # the explorer opens a model or scene file
                    fi
                    ;;
            esac
            ;;
    esac
    # Bash replaces only the part of the word after its last '=' or ':'; drop what stays.
    local replaced=${COMP_WORDS[COMP_CWORD]:-}
    if [[ $cur != "$replaced" && $cur == *"$replaced" ]]; then
        local kept=${cur%"$replaced"}
        COMPREPLY=("${COMPREPLY[@]#"$kept"}")
    fi
}
complete -F _shadowlab shadowlab
"""


def explorer_options(program):
    """The explorer's options, from the usage line that shows them: "[--settings file.json]"."""
    return [Option([name], value, "") for line in program.usage
            for name, value in re.findall(r"\[(--[a-z][a-z-]*)(?: ([^\]]*?))?(?: \.\.\.)?\]", line)]


def takes(value):
    if not value:
        return ""
    return "dir" if value == "dir" else "file" if "file" in value else "value"


def completion(program, presets):
    explorer = explorer_options(program)
    by_command = [(c.name, c.options) for c in program.commands] + [("", program.options + explorer)]
    option_cases, take_cases = [], []
    for name, options in by_command:
        option_cases.append("        %s) echo '%s' ;;" % (name or "''", " ".join(n for o in options for n in o.names)))
        take_cases += ["        '%s %s') echo %s ;;" % (name, n, takes(o.value)) for o in options if o.value for n in o.names]
    value_cases = []
    for s in program.settings:
        values = s.get("choices") or (["true", "false"] if s["type"] == "bool" else [])
        if values:
            value_cases.append("        %s) echo '%s' ;;" % (s["key"], " ".join(values)))
    scenes = next(s["choices"] for s in program.settings if s["key"] == "scene")
    text = COMPLETION
    for marker, value in [
        ("@COMMANDS@", " ".join(c.name for c in program.commands)),
        ("@KEYS@", " ".join(s["key"] for s in program.settings)),
        ("@SCENES@", " ".join(scenes)),
        ("@PRESETS@", " ".join(presets)),
        ("@OPTIONS@", "\n".join(option_cases)),
        ("@TAKES@", "\n".join(take_cases)),
        ("@VALUES@", "\n".join(value_cases)),
    ]:
        text = text.replace(marker, value)
    return text


# ---- markdown ---------------------------------------------------------------------------------

GENERATED = "<!-- Generated by scripts/docs.sh from %s; do not edit. -->"


def md_text(text):
    """Prose for markdown: a '<' outside `code` would start an HTML tag."""
    parts = text.split("`")
    return "`".join(p if i % 2 else p.replace("<", "&lt;") for i, p in enumerate(parts))


def md_option(option):
    names = ", ".join("`%s`" % n for n in option.names)
    if option.value:
        names = ", ".join("`%s <%s>`" % (n, option.value) for n in option.names)
    return "- %s: %s" % (names, md_text(option.text))


def cli_markdown(program):
    out = ["# Command line", "", GENERATED % "`shadowlab --help` and `shadowlab help <command>`", "",
           "```text"] + ["shadowlab " + line.removeprefix("shadowlab ") for line in program.usage] + ["```", "",
           md_text(program.intro), "", "| Command | What it does |", "| --- | --- |"]
    for c in program.commands:
        out.append("| [`%s`](#shadowlab-%s) | %s |" % (c.name, c.name, md_cell(c.summary)))
    out += ["", "Options of the program itself:", ""] + [md_option(o) for o in program.options]
    out += ["", "Every setting a `--set` can change is in [settings.md](settings.md)."]
    for c in program.commands:
        out += ["", "## shadowlab %s" % c.name, "", md_text(c.description), "", "```text", c.usage, "```", ""]
        out += [md_option(o) for o in c.options]
    return "\n".join(out) + "\n"


def md_cell(text):
    return md_text(text).replace("|", "\\|")


def settings_markdown(program):
    out = ["# Settings", "", GENERATED % "`shadowlab settings --json`, the settings table", "",
           "Every key is set the same way everywhere: `--set key=value` on the command line (any command, and the "
           "explorer), `\"key\": value` in a settings file (`--settings file.json`), and the explorer's docks. "
           "The defaults are the seed scene's: a scene sets its own light and camera "
           "(`shadowlab settings --scene NAME` lists them)."]
    group = None
    for s in program.settings:
        if key_group(s["key"]) != group:
            group = key_group(s["key"])
            out += ["", "## %s" % group, "", "| Key | Type | Range | Default | What it does |", "| --- | --- | --- | --- | --- |"]
        out.append("| `%s` | %s | %s | `%s` | %s |" % (s["key"], s["type"], md_cell(s["range"]), s["default"], md_cell(s["help"])))
    return "\n".join(out) + "\n"


def main(argv):
    if len(argv) < 4 or argv[1] not in ("man", "completion", "cli-md", "settings-md"):
        sys.exit(__doc__)
    kind, binary, output = argv[1:4]
    program = read_program(binary)
    if kind == "man":
        text = man_page(program)
    elif kind == "completion":
        # The artifact presets are the files of resources/presets (ArtifactPresets.h).
        presets_dir = argv[4]
        text = completion(program, sorted(f[:-5] for f in os.listdir(presets_dir) if f.endswith(".json")))
    elif kind == "cli-md":
        text = cli_markdown(program)
    else:
        text = settings_markdown(program)
    with open(output, "w", encoding="utf-8") as f:
        f.write(text)


if __name__ == "__main__":
    main(sys.argv)
