"""The table of contents (notebooks/contents.toml): what the runner and the book read, and what it refuses."""

from __future__ import annotations

import shutil
import tomllib
from pathlib import Path

import pytest

from vibration.book.publishing.book import ChapterPage, parts
from vibration.book.publishing.front_page import toctree_markdown
from vibration.book.publishing.registry import CONTENTS_FILE, add_chapter, chapter_packages, read_contents
from vibration.book.publishing.report import discover
from vibration.book.publishing.template import new_chapter
from vibration.physics.model import ParameterError

ROOT = Path(__file__).resolve().parents[2]


def _project(tmp_path: Path) -> Path:
    """A copy of the project's table of contents with an empty notebook for every chapter it lists."""
    root = tmp_path / "project"
    (root / "notebooks").mkdir(parents=True)
    shutil.copy(ROOT / CONTENTS_FILE, root / CONTENTS_FILE)
    for stem in read_contents(ROOT).order:
        (root / "notebooks" / f"{stem}.ipynb").write_text("{}")
    return root


def test_the_contents_list_every_notebook_once_front_page_first():
    contents = read_contents(ROOT)
    raw = tomllib.loads((ROOT / CONTENTS_FILE).read_text(encoding="utf-8"))
    on_disk = sorted(p.stem for p in (ROOT / "notebooks").glob("*.ipynb"))
    assert sorted(contents.order) == on_disk and len(set(contents.order)) == len(on_disk)
    assert contents.order[0] == raw["front"] and contents.part_of(raw["front"]) is None
    assert [p.title for p in contents.parts] == [t["title"] for t in raw["parts"]]
    assert [c.name for c in discover(ROOT)] == list(contents.order)  # the runner's order is the book's
    assert set(contents.order) <= set(chapter_packages())  # every chapter has its package


def test_an_unlisted_notebook_a_missing_one_and_a_repeated_one_are_refused(tmp_path):
    root = _project(tmp_path)
    (root / "notebooks" / "13_stray.ipynb").write_text("{}")
    with pytest.raises(ParameterError, match=r"notebooks/13_stray.ipynb is in no part of notebooks/contents.toml"):
        read_contents(root)
    (root / "notebooks" / "13_stray.ipynb").unlink()
    (root / "notebooks" / "08_tmd.ipynb").unlink()
    with pytest.raises(ParameterError, match=r"lists 08_tmd, which notebooks/ does not hold"):
        read_contents(root)
    (root / "notebooks" / "08_tmd.ipynb").write_text("{}")
    text = (root / CONTENTS_FILE).read_text()
    (root / CONTENTS_FILE).write_text(text.replace('"12_real_oscillator",', '"12_real_oscillator", "08_tmd",'))
    with pytest.raises(ParameterError, match=r"lists 08_tmd more than once"):
        read_contents(root)
    (root / CONTENTS_FILE).write_text("title = [")
    with pytest.raises(ParameterError, match=r"is not valid TOML"):
        read_contents(root)
    (root / CONTENTS_FILE).unlink()
    with pytest.raises(ParameterError, match=r"contents.toml is missing"):
        read_contents(root)


def test_a_new_chapter_joins_the_part_its_author_names(tmp_path):
    root = _project(tmp_path)
    written = new_chapter("13_damping_map", root, part=2, package_dir=tmp_path / "pkg")
    contents = read_contents(root)
    assert contents.part_of("13_damping_map").title == contents.parts[1].title  # Part II, not by its number
    assert contents.parts[1].chapters[-1] == "13_damping_map"
    assert contents.parts[2].chapters == ("12_real_oscillator",)
    assert root / "notebooks" / "13_damping_map.ipynb" in written
    add_chapter("14_wheel", root, 3)
    (root / "notebooks" / "14_wheel.ipynb").write_text("{}")
    assert read_contents(root).parts[2].chapters == ("12_real_oscillator", "14_wheel")


def test_a_part_that_does_not_exist_is_refused_before_anything_is_written(tmp_path):
    root = _project(tmp_path)
    before = (root / CONTENTS_FILE).read_text()
    with pytest.raises(ParameterError, match=r"part = 4 is not a part of notebooks/contents.toml: allowed 1 to 3"):
        new_chapter("13_topic", root, part=4, package_dir=tmp_path / "pkg")
    assert (root / CONTENTS_FILE).read_text() == before
    assert not (root / "notebooks" / "13_topic.ipynb").exists() and not (tmp_path / "pkg").exists()


def test_a_project_without_contents_gets_one_part_holding_its_chapter(tmp_path):
    add_chapter("01_only", tmp_path, 2)
    (tmp_path / "notebooks" / "01_only.ipynb").write_text("{}")
    contents = read_contents(tmp_path)
    assert contents.order == ("01_only",) and contents.front == ""


def test_the_book_groups_chapters_by_their_part_not_by_their_number():
    pages = [
        ChapterPage(name="00_front", notebook=None),
        ChapterPage(name="01_a", notebook=None, part="First"),
        ChapterPage(name="13_late", notebook=None, part="First"),
        ChapterPage(name="02_b", notebook=None, part="Second"),
    ]
    assert [(title, [p.name for p in members]) for title, members in parts(pages)] == [
        ("First", ["01_a", "13_late"]),
        ("Second", ["02_b"]),
    ]
    tree = toctree_markdown(pages)
    assert tree.index(":caption: First") < tree.index("13_late") < tree.index(":caption: Second")
