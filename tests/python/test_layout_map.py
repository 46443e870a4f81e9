"""The map "What is where" of docs/development.md against the repository: every folder of the
source trees is named in it, and every path it names exists."""
import pathlib
import re

# folders every one of whose sub-folders the map must name; python/rockingwall/: its packages
TREES = ["fmu_src", "host", "scripts", "reference", "tests"]
PACKAGES = "python/rockingwall"
SKIPPED = re.compile(r"^(\.|__pycache__$)|\.egg-info$")
# a name in the right column taken as a path: it has a folder part or a file extension
PATHLIKE = re.compile(r"^[\w.-]+(/[\w.-]+)*/?$")
EXTENSION = re.compile(r"\.(c|h|py|sh|cmake|txt|xml|toml|md|json)$")


def map_rows(text):
    """[(path tokens, what tokens)] of the table under "## What is where"."""
    section = text.split("## What is where", 1)[1].split("\n## ", 1)[0]
    rows = []
    for line in section.splitlines():
        cells = line.split("|")
        if len(cells) < 4 or set(cells[1].strip()) <= set("-") or cells[1].strip() == "path":
            continue
        rows.append((re.findall(r"`([^`]+)`", cells[1]), re.findall(r"`([^`]+)`", "|".join(cells[2:-1]))))
    return rows


def _pathlike(token):
    return bool(PATHLIKE.match(token)) and ("/" in token or bool(EXTENSION.search(token)))


def named_paths(rows):
    """Every path the map names, each as its candidates relative to the repository: the left
    column as written; a name in the right column relative to the row's folder (when the row names
    one folder), or else to the repository."""
    paths = []
    for left, right in rows:
        paths += [(p,) for p in left]
        folders = [p for p in left if p.endswith("/")]
        base = folders[0] if len(folders) == 1 else ""
        paths += [(base + t, t) if base else (t,) for t in right if _pathlike(t)]
    return paths


def folders_to_name(root):
    """The folders the map must name, each as "path/"."""
    found = []
    for tree in TREES:
        top = root / tree
        found += [d for d in top.rglob("*") if d.is_dir()
                  and not any(SKIPPED.search(part) for part in d.relative_to(top).parts)]
    found += [d for d in (root / PACKAGES).rglob("*") if (d / "__init__.py").is_file()]
    return sorted(d.relative_to(root).as_posix() + "/" for d in found)


def problems(root, text):
    """(folders not named, named paths that do not exist)."""
    named = named_paths(map_rows(text))
    folders = {p.rstrip("/") + "/" for candidates in named for p in candidates if (root / p).is_dir()}
    unnamed = [f for f in folders_to_name(root) if f not in folders]
    missing = sorted({candidates[0] for candidates in named if not any((root / p).exists() for p in candidates)})
    return unnamed, missing


def test_every_folder_is_named_and_every_named_path_exists(repo):
    unnamed, missing = problems(repo, (repo / "docs" / "development.md").read_text())
    assert unnamed == [], f"folders missing from docs/development.md's map: {unnamed}"
    assert missing == [], f"paths in docs/development.md's map that do not exist: {missing}"


def test_the_check_finds_an_unnamed_folder_and_a_stale_path(tmp_path):
    """A tree with one folder the map leaves out and a map naming a file that is not there."""
    for d in ["fmu_src/wall", "fmu_src/new", "host", "scripts", "reference", "tests/c", "tests/c/__pycache__",
              "python/rockingwall/sweep", "python/rockingwall/_bin"]:
        (tmp_path / d).mkdir(parents=True)
    for f in ["fmu_src/wall/rw_physics.h", "python/rockingwall/__init__.py", "python/rockingwall/sweep/__init__.py"]:
        (tmp_path / f).write_text("")
    text = ("## What is where\n\n| path | what |\n|---|---|\n"
            "| `fmu_src/` | `CMakeLists.txt` |\n"
            "| `fmu_src/wall/` | `rw_physics.h`, `rw_gone.c`, `Q(q)` and `python/rockingwall/__init__.py` |\n"
            "| `host/`, `scripts/`, `reference/` | |\n| `tests/` | `c/` |\n"
            "| `python/rockingwall/` | `sweep/` |\n\n## Next\n| `nothing/` | |\n")
    unnamed, missing = problems(tmp_path, text)
    assert unnamed == ["fmu_src/new/"]
    assert missing == ["fmu_src/CMakeLists.txt", "fmu_src/wall/rw_gone.c"]
