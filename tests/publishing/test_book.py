"""The book: Sphinx + myst-nb + sphinx-book-theme over the notebooks, opened offline in Chromium.

The site is built once per session from the committed notebooks (their stored outputs, no
kernel), which exercises the whole publishing stack in seconds; the runner's own end-to-end
path (papermill, then the book) is checked with a small run carrying ``-p c_low 0.05``.
"""

from __future__ import annotations

import json
import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

import pytest
from conftest import CHROMIUM, SCREENSHOTS, open_offline

from vibration.book.publishing import report
from vibration.book.publishing.book import split_help, summary
from vibration.book.publishing.registry import read_contents

# every test here builds on a study or a book that takes seconds: make test-slow runs them
pytestmark = pytest.mark.slow

ROOT = Path(__file__).resolve().parents[2]
NOTEBOOKS = sorted(p for p in (ROOT / "notebooks").glob("*.ipynb"))
CHAPTERS = [p.stem for p in NOTEBOOKS if not p.stem.startswith("00_")]
CONTENTS = read_contents(ROOT)


@pytest.fixture(scope="module")
def site(committed_book) -> Path:
    """The HTML book from the committed notebooks (the print edition has its own, slow, fixture)."""
    return committed_book


@pytest.fixture(scope="module")
def printed(tmp_path_factory) -> Path:
    """The book with its print edition (Chromium prints it twice: about a minute and a half)."""
    if not os.path.exists(CHROMIUM):
        pytest.skip(f"{CHROMIUM} is missing: make browser installs it")
    out = tmp_path_factory.mktemp("printed") / "report"
    report.book_from_sources(report.discover(ROOT), out, pdf=True)
    return out


def _pages(site: Path) -> list[Path]:
    return sorted(site.glob("*.html"))


# ------------------------------------------------------------------ static checks


def test_every_chapter_and_the_front_page_are_built(site):
    assert (site / "index.html").is_file()
    for name in CHAPTERS:
        assert (site / f"{name}.html").is_file(), name
    assert (site / "search.html").is_file() and (site / "searchindex.js").is_file()


def test_no_page_loads_from_the_network(site):
    from vibration.book.publishing.mathml import external_urls

    for page in _pages(site):
        text = page.read_text(encoding="utf-8")
        loading = "".join(re.findall(r"<(?:script|link|img|iframe)\b[^>]*>", text))
        assert external_urls(loading) == [], page.name
        assert not re.search(r"<script[^>]*(require|mathjax)[^>]*>", text, re.I), page.name
        assert "html-manager" not in text and "unpkg" not in text, page.name


def test_chapter_titles_carry_no_timing(site):
    for page in _pages(site):
        title = re.search(r"<title>(.*?)</title>", page.read_text(encoding="utf-8"), re.S).group(1)
        assert not re.search(r"\d+(\.\d+)? s\b", title), title


def test_parameters_cell_is_a_table_of_name_value_unit_meaning(site):
    text = (site / "01_reproduction.html").read_text(encoding="utf-8")
    block = re.search(r'<div class="vib-parameters">(.*?)</div>', text, re.S).group(1)
    assert "<th>symbol</th><th>value</th><th>unit</th><th>meaning</th><th>set with <code>-p</code></th>" in block
    assert "<td>c<sub>low</sub></td><td>0.1</td><td>N s/m</td>" in block and "<code>c_low</code>" in block
    assert "c_low: float" not in text  # the cell's source is not shown


def test_no_banner_with_the_papers_parameters(site):
    for page in _pages(site):
        assert "vib-banner" not in page.read_text(encoding="utf-8"), page.name


def test_every_display_equation_of_the_sources_is_mathml(site):
    for nb_path in NOTEBOOKS:
        nb = json.loads(nb_path.read_text(encoding="utf-8"))
        source = "\n".join("".join(c["source"]) for c in nb["cells"] if c["cell_type"] == "markdown")
        n_display = len(re.findall(r"\$\$(.+?)\$\$", source, re.S))
        name = "index" if nb_path.stem.startswith("00_") else nb_path.stem
        html_text = (site / f"{name}.html").read_text(encoding="utf-8")
        assert html_text.count('<math display="block"') >= n_display, nb_path.name
        assert "vib-tex-fallback" not in html_text, nb_path.name


def test_figures_and_tables_are_numbered_per_chapter_from_one(site):
    numbered = 0
    for name in CHAPTERS:
        text = (site / f"{name}.html").read_text(encoding="utf-8")
        chap = int(name.split("_")[0])
        for kind in ("Figure", "Table"):
            found = re.findall(rf'<span class="caption-number">{kind} (\d+)\.(\d+) </span>', text)
            assert all(int(c) == chap for c, _ in found), (name, kind, found)
            numbers = sorted({int(n) for _, n in found})
            assert numbers == list(range(1, len(numbers) + 1)), (name, kind, numbers)
            numbered += len(numbers)
    assert numbered >= 1


def test_the_notebooks_references_read_as_the_book_numbers_them(site):
    """A notebook's Markdown writes each reference's number for JupyterLab ({numref}`Figure 4.1 <fig-x>`); the book
    numbers and links the same reference itself, and the two agree."""
    role = re.compile(r"\{numref\}`([^`<]*?)\s*<([^`<>]+)>`")
    checked = 0
    for path in NOTEBOOKS:
        page = site / ("index.html" if path.stem == CONTENTS.front else f"{path.stem}.html")
        html = page.read_text(encoding="utf-8")
        book = dict(
            re.findall(
                r'<a class="reference internal" href="#([^"]+)"><span class="std std-numref">([^<]+)</span>', html
            )
        )
        cells = json.loads(path.read_text(encoding="utf-8"))["cells"]
        for text, label in (
            m.groups() for c in cells if c["cell_type"] == "markdown" for m in role.finditer("".join(c["source"]))
        ):
            assert book.get(label) == text, (path.stem, label, text, book.get(label))
            checked += 1
        # the outputs' references ("the table" in JupyterLab) are numbered too
        assert [t for t in book.values() if not re.fullmatch(r"(Figure|Table) \d+(\.\d+)?", t)] == [], path.stem
    assert checked >= 40


def test_banner_lists_own_and_other_changes():
    from vibration.book.publishing.book import Parameter, banner_html

    own = [
        Parameter(name="k", value=30.0, default=20.0, meaning="spring stiffness", unit="N/m", paper=True),
        Parameter(name="m", value=1.0, default=1.0, meaning="mass", unit="kg", paper=True),
    ]
    other = [Parameter(name="c_low", value=0.05, default=0.1, meaning="low damping", unit="N s/m", paper=True)]
    assert banner_html([p for p in own if p.name == "m"], []) == ""
    text = banner_html(own, own[:1] + other)
    assert "k (spring stiffness, <code>-p k</code>) = <strong>30 N/m</strong>; the paper: 20 N/m" in text
    assert "Also changed in this run" in text and "c_low" in text
    assert "<code>m</code>" not in text
    only_other = banner_html(own[1:], other)
    assert "Not the paper" not in only_other and "not used on this page" in only_other


def test_split_help_and_summary_helpers():
    assert split_help("spring stiffness, N/m") == ("spring stiffness", "N/m")
    assert split_help("output samples, 1") == ("output samples", "")
    import nbformat

    nb = nbformat.v4.new_notebook()
    nb.cells = [nbformat.v4.new_markdown_cell("# T\n\n**Overview.** First plain. Then $x$.")]
    assert summary(nb) == "First plain."


@pytest.mark.slow
@pytest.mark.browser
def test_pdf_has_a_page_or_more_per_chapter(printed):
    from pypdf import PdfReader

    reader = PdfReader(str(printed / "report.pdf"))
    assert len(reader.pages) >= len(CHAPTERS) + 1
    texts = [" ".join((page.extract_text() or "").replace("\u2019", "'").split()) for page in reader.pages]
    assert texts[0].startswith(CONTENTS.title) or CONTENTS.title in texts[0]
    starts = []
    for nb_path in [p for p in NOTEBOOKS if not p.stem.startswith("00_")]:
        nb = json.loads(nb_path.read_text(encoding="utf-8"))
        title = "".join(nb["cells"][0]["source"]).splitlines()[0].lstrip("# ").strip()
        head = " ".join(title.split()[:4])
        pages = [
            i
            for i, t in enumerate(texts)
            if re.sub(r"^vibdoc\d+mark ", "", t.replace(CONTENTS.title, "", 1).strip()).startswith(head)
        ]
        later = [i for i in pages if i > (starts[-1] if starts else 0)]
        assert later, f"{title!r} is not in the PDF after the previous chapter ({pages})"
        starts.append(later[0])  # the first after the previous chapter: the answers repeat the chapters' titles
    assert len(set(starts)) == len(starts) and starts == sorted(starts), starts
    assert "1 /" in texts[0] or texts[0].strip().endswith(f"1 / {len(texts)}") or "1 / " in texts[0]


# ---------------------------------------------------------------- browser checks


WIDE_JS = """() => {
    const col = document.querySelector('article.bd-article').getBoundingClientRect().right;
    const sel = 'article table, article img, article svg, article .vib-panel, article figure';
    return [...document.querySelectorAll(sel)]
        .filter(e => e.getBoundingClientRect().right > col + 2)
        .map(e => e.tagName + ' ' + (e.querySelector('caption') || e).textContent.slice(0, 60));
}"""


@pytest.fixture(scope="module")
def visited(browser, site) -> dict:
    """Every page opened once at 1280 px: what it loaded from outside, its errors, its sidebar, what is too wide
    (about 30 s: the tests that read it run with the slow tests)."""
    out = {}
    for path in _pages(site):
        page, outside, errors = open_offline(browser, path, viewport=(1280, 900))
        page.wait_for_timeout(100)
        facts = {"outside": outside, "errors": errors}
        if path.name not in ("search.html", "genindex.html"):
            hrefs = page.eval_on_selector_all(".bd-sidebar-primary a", "els => els.map(e => e.getAttribute('href'))")
            facts["targets"] = {h.split("#")[0] for h in hrefs if h}
            facts["sidebar"] = page.inner_text(".bd-sidebar-primary")
            facts["wide"] = page.evaluate(WIDE_JS)
        out[path] = facts
        page.close()
    return out


@pytest.mark.slow
@pytest.mark.browser
def test_every_page_loads_offline_without_errors(visited):
    for path, facts in visited.items():
        assert facts["outside"] == [], (path.name, facts["outside"])
        assert facts["errors"] == [], (path.name, facts["errors"])


@pytest.mark.slow
@pytest.mark.browser
def test_every_chapter_is_reachable_from_the_sidebar_of_every_page(visited):
    for path, facts in visited.items():
        if "targets" not in facts:
            continue
        targets = facts["targets"]
        for name in CHAPTERS:
            assert f"{name}.html" in targets or (path.stem == name and "" in targets), (path.name, name)
        for part in CONTENTS.parts:
            assert part.title in facts["sidebar"], (path.name, part.title)


@pytest.mark.slow
@pytest.mark.browser
def test_nothing_is_wider_than_the_text_column_at_1280_px(visited):
    wide = {path.name: facts["wide"] for path, facts in visited.items() if facts.get("wide")}
    assert wide == {}


@pytest.mark.browser
def test_previous_and_next_links(browser, site):
    page, _, _ = open_offline(browser, site / f"{CHAPTERS[1]}.html")
    prev = page.get_attribute("a.left-prev", "href")
    nxt = page.get_attribute("a.right-next", "href")
    assert prev.startswith(CHAPTERS[0]) and nxt.startswith(CHAPTERS[2])
    page.close()


@pytest.mark.browser
def test_search_finds_dormand(browser, site):
    page, outside, errors = open_offline(browser, site / "search.html")
    page.goto((site / "search.html").as_uri() + "?q=Dormand")
    page.wait_for_selector("#search-results ul li a", timeout=20_000)
    links = page.eval_on_selector_all("#search-results ul li a", "els => els.map(e => e.getAttribute('href'))")
    assert any("03_solver_accuracy" in h for h in links), links
    # each result shows the page's text around the word, also from disk (the pages' text ships with the book)
    page.wait_for_function("document.querySelectorAll('#search-results ul li p.context').length > 0")
    contexts = page.eval_on_selector_all("#search-results ul li p.context", "els => els.map(e => e.innerText)")
    assert any("Dormand" in c for c in contexts), contexts
    assert errors == [] and outside == []
    page.close()


@pytest.mark.browser
def test_code_cells_are_folded_and_open_on_click(browser, site):
    page, _, _ = open_offline(browser, site / "01_reproduction.html", viewport=(1280, 900))
    folded = page.locator("details.hide.above-input")
    assert folded.count() >= 3
    first = folded.first
    assert first.get_attribute("open") is None
    code = first.locator("pre")
    assert not code.is_visible()
    first.locator("summary").click()
    page.wait_for_timeout(100)
    assert first.get_attribute("open") is not None
    assert code.is_visible()
    Path(SCREENSHOTS).mkdir(parents=True, exist_ok=True)
    first.scroll_into_view_if_needed()
    page.screenshot(path=str(Path(SCREENSHOTS) / "book-folded-cell-open.png"))
    page.close()


@pytest.mark.browser
def test_equations_render_as_mathml_with_size(browser, site):
    page, _, _ = open_offline(browser, site / "01_reproduction.html")
    boxes = page.eval_on_selector_all('math[display="block"]', "els => els.map(e => e.getBoundingClientRect().height)")
    assert boxes and min(boxes) > 5
    page.close()


def test_a_mention_of_another_chapter_links_to_it(site):
    """'chapter 4' in the text is a link to chapter 4's page (not when a page names itself, nor in headings or
    in tables, which are the chapters' raw HTML)."""
    from bs4 import BeautifulSoup

    from vibration.book.publishing.sphinx_ext import chapter_mentions

    linked, unlinked = 0, []
    for page in _pages(site):
        article = BeautifulSoup(page.read_text(encoding="utf-8"), "html.parser").select_one("article")
        if article is None:
            continue
        for element in article.select("div.cell_input, script, style, h1, h2, h3, h4, table"):
            element.decompose()
        here = int(page.stem[:2]) if page.stem[:2].isdigit() else None
        for text in article.find_all(string=True):
            link = text.find_parent("a")
            named = [n for _, n in chapter_mentions(str(text)) if n not in (None, here)]
            if named and not (link is not None and named == [int(link.get_text().split()[-1])]):
                unlinked.append((page.name, str(text)[:60]))
        numbers = [(a, a.get_text().split()[-1]) for a in article.select("a") if a.get_text().split()]
        linked += sum(n.isdigit() and a["href"].startswith(f"{int(n):02d}_") for a, n in numbers)
    assert linked > 50 and unlinked == []


INLINE_MATH_JS = """() => [...document.querySelectorAll('article p math:not([display=block]) mi')].map(mi => {
    const s = getComputedStyle(mi), p = getComputedStyle(mi.closest('p'));
    return {text: mi.textContent, letter: mi.classList.contains('vib-it'), family: s.fontFamily === p.fontFamily,
            transform: s.textTransform, style: s.fontStyle, upright: mi.getAttribute('mathvariant') === 'normal'};
})"""


@pytest.mark.browser
def test_inline_math_is_set_in_the_texts_typeface(browser, site):
    """A letter of inline math is the text's own italic, not the math font's mathematical italic; a name such as
    sin and a letter marked upright (a unit) stay upright."""
    page, _, _ = open_offline(browser, site / "01_reproduction.html")
    found = page.evaluate(INLINE_MATH_JS)
    page.close()
    assert len(found) > 20 and any(len(f["text"]) > 1 for f in found)
    assert [f for f in found if not f["family"] or f["transform"] != "none"] == []
    assert [f for f in found if (f["style"] == "italic") != (len(f["text"]) == 1 and not f["upright"])] == []


@pytest.mark.browser
def test_front_page_reports_computed_headline(browser, site):
    page, _, errors = open_offline(browser, site / "index.html", viewport=(1280, 900))
    text = page.inner_text("article")
    assert "The Effect of Resonance and Damping on Dynamic System Stability" in text
    assert "2.237 m" in text  # the exact resonance amplitude, computed by the front page
    for name in CHAPTERS:
        assert page.locator(f"article a[href^='{name}']").count() >= 1, name
    Path(SCREENSHOTS).mkdir(parents=True, exist_ok=True)
    page.screenshot(path=str(Path(SCREENSHOTS) / "book-front.png"), full_page=True)
    assert errors == []
    page.close()


# ------------------------------------------------------------------- end to end


# ---------------------------------------------------------------------- layers


def test_lint_imports_passes():
    proc = subprocess.run([str(Path(sys.executable).parent / "lint-imports")], capture_output=True, text=True, cwd=ROOT)
    assert proc.returncode == 0, proc.stdout + proc.stderr


def test_lint_imports_fails_on_a_forbidden_import(tmp_path):
    shutil.copytree(ROOT / "src", tmp_path / "src", ignore=shutil.ignore_patterns("__pycache__", "*.egg-info"))
    shutil.copy(ROOT / "pyproject.toml", tmp_path / "pyproject.toml")
    model = tmp_path / "src" / "vibration" / "physics" / "model.py"
    model.write_text(model.read_text(encoding="utf-8") + "\nfrom ..book.presentation import tables  # noqa\n")
    env = {"PYTHONPATH": str(tmp_path / "src"), "PATH": str(Path(sys.executable).parent)}
    proc = subprocess.run(
        [str(Path(sys.executable).parent / "lint-imports"), "--no-cache"],
        capture_output=True,
        text=True,
        cwd=tmp_path,
        env=env,
    )
    assert proc.returncode != 0, proc.stdout
    assert "BROKEN" in proc.stdout and "vibration.physics.model" in proc.stdout, proc.stdout


@pytest.mark.slow
@pytest.mark.browser
def test_the_print_edition_has_a_title_page_contents_and_bookmarks(printed):
    """Title page first, a contents whose page numbers open their chapters, one bookmark per chapter and appendix."""
    from pypdf import PdfReader

    reader = PdfReader(str(printed / "report.pdf"))
    texts = [" ".join((page.extract_text() or "").replace("\u2019", "'").split()) for page in reader.pages]
    assert texts[0].startswith(CONTENTS.title), texts[0][:200]
    contents = next(i for i, t in enumerate(texts) if t.startswith("Contents"))
    listing = texts[contents].removeprefix("Contents").split(f" {CONTENTS.title} ")[0]  # the header line ends it
    stop = r"(?= (?:\d+\. |Part |Table |Glossary |Running |Using |Answers |Licences|References|Overview)|$)"
    entries = [(t.strip(), p) for t, p in re.findall(r"(.+?) (\d{1,3})" + stop, listing)]
    entries = [(re.sub(r"^Part [IVX]+: .*? (?=\d+\. )", "", t), p) for t, p in entries]
    from vibration.book.publishing.appendices import APPENDICES

    assert len(entries) == len(CHAPTERS) + 1 + len(APPENDICES), entries  # the front page, the chapters, appendices
    assert entries[0][0].replace("\ufb01", "fi") == "Overview and findings", entries[0]
    for title, page in entries[1:]:
        opened = texts[int(page) - 1]
        head = " ".join(title.split()[:3])
        assert head in opened[:400], (title, page, opened[:200])

    def titles(items):
        for item in items:
            if isinstance(item, list):
                yield from titles(item)
            else:
                yield item.title

    marks = list(titles(reader.outline))
    for title, _ in entries[1:]:
        assert any(" ".join(title.split()[:3]) in " ".join(m.replace("\u2019", "'").split()) for m in marks), title
    assert {"Title page", "Contents", "References"} <= set(marks)


# ------------------------------------------------------------------ proofreading the reader's text


def _reader_pages(site: Path) -> list[Path]:
    return [p for p in _pages(site) if p.name not in ("genindex.html", "search.html")]


def test_the_reader_text_has_no_code_notation(site):
    """No underscored code names, e-notation, ^ powers or sqrt( outside code and maths (issue 22)."""
    from vibration.book.publishing.proofread import code_notation

    found = {p.name: code_notation(p.read_text(encoding="utf-8")) for p in _reader_pages(site)}
    assert {k: v[:10] for k, v in found.items() if v} == {}


#: Tools and libraries a chapter page's visible text does not name (the paper's own words, quoted in chapter 2,
#: name its solver; integration methods such as RK45 or DOP853 are the subject of chapter 3, not tools).
TOOLS = re.compile(
    r"\b(papermill|nbval|pytest|sphinx|jupyter\w*|numpy|numba|matplotlib|ipywidgets|playwright|chromium|dask)\b"
    r"|\bpython \d",
    re.I,
)


def test_chapter_pages_name_no_tool_and_the_appendix_names_the_versions(site):
    """The versions a notebook prints stay in the notebook; the book names its build's in "Using the package"."""
    from bs4 import BeautifulSoup

    found = {}
    for page in [site / "index.html", *(site / f"{name}.html" for name in CHAPTERS)]:
        article = BeautifulSoup(page.read_text(encoding="utf-8"), "html.parser").select_one("article")
        for element in article.select("div.cell_input, script, style"):
            element.decompose()
        text = " ".join(article.get_text(" ").split())
        found[page.name] = [text[max(0, m.start() - 30) : m.end() + 30] for m in TOOLS.finditer(text)]
    assert {k: v for k, v in found.items() if v} == {}
    using = BeautifulSoup((site / "using.html").read_text(encoding="utf-8"), "html.parser").get_text(" ")
    import numpy
    import scipy

    assert f"NumPy {numpy.__version__}" in using and f"SciPy {scipy.__version__}" in using


def test_the_front_page_summarises_the_chapters_instead_of_repeating_them(site):
    """Of Parts II and III the front page gives each chapter's headline (at most one sentence shared word for word
    with the chapter's page per chapter), not its whole list of key results."""
    from vibration.book.publishing.proofread import sentences

    def said(page: Path) -> set[str]:
        return set(sentences(page.read_text(encoding="utf-8")))

    front = said(site / "index.html")
    later = [name for name in CHAPTERS if int(name[:2]) >= 6]
    shared = {name: front & said(site / f"{name}.html") for name in later}
    assert all(len(s) <= 1 for s in shared.values()), {k: sorted(v) for k, v in shared.items() if len(v) > 1}


def test_no_sentence_repeats_on_a_chapter_page(site):
    """A chapter's summary says what its sections found in new words: no sentence of eight or more words appears
    twice in a chapter page's main text (code, folds and exercises left out)."""
    from vibration.book.publishing.proofread import repeated_sentences

    found = {name: repeated_sentences((site / f"{name}.html").read_text(encoding="utf-8")) for name in CHAPTERS}
    assert {k: [s[:80] for s in v] for k, v in found.items() if v} == {}


def test_no_paragraph_repeats_on_a_page(site):
    """A paragraph, list item or caption appears once per page, also when only its rounding differs."""
    from vibration.book.publishing.proofread import repeated_paragraphs

    found = {p.name: repeated_paragraphs(p.read_text(encoding="utf-8")) for p in _reader_pages(site)}
    assert {k: [t[:80] for t in v] for k, v in found.items() if v} == {}


def test_every_figure_has_alt_text_that_describes_it(site):
    from vibration.book.publishing.proofread import figures_without_alt

    found = {p.name: figures_without_alt(p.read_text(encoding="utf-8")) for p in _reader_pages(site)}
    assert {k: v for k, v in found.items() if v} == {}


def test_every_cited_work_is_in_the_references(site):
    """Each "Surname (year)" or "Surname et al. year" in the text names a work of the bibliography."""
    from vibration.book.presentation.references import find
    from vibration.book.publishing.proofread import _article

    pattern = re.compile(r"\b([A-Z][a-z]+)(?:,? (?:and|&) [A-Z][a-z]+| et al\.)?,? \(?((?:19|20)\d\d)\b(?![\d.])")
    missing = set()
    for page in _reader_pages(site):
        text = _article(page.read_text(encoding="utf-8")).get_text(" ")
        for surname, year in pattern.findall(text):
            if surname not in {"December", "January", "Part", "Table", "Figure", "Chapter"} and not find(
                surname, int(year)
            ):
                missing.add((page.name, surname, year))
    assert missing == set()


# ------------------------------------------------------------------ teaching: downloads, exercises, tracks (issue 28)


def test_every_chapter_page_offers_its_notebook_and_the_package(site):
    """Each chapter's download links resolve inside the build: its notebook with outputs, and the wheel."""
    import zipfile

    import nbformat

    wheels = list((site / "_static" / "downloads").glob("vibration-*.whl"))
    assert len(wheels) == 1 and "vibration/__init__.py" in zipfile.ZipFile(wheels[0]).namelist()
    for page in CHAPTERS:
        html = (site / f"{page}.html").read_text(encoding="utf-8")
        links = re.findall(r'href="(_static/downloads/[^"]+)"', html)
        assert f"_static/downloads/{page}.ipynb" in links and f"_static/downloads/{wheels[0].name}" in links, page
        nb = nbformat.read(site / "_static" / "downloads" / f"{page}.ipynb", as_version=4)
        assert any(c.get("outputs") for c in nb.cells if c.cell_type == "code"), page
        assert "Worked answer" not in nbformat.writes(nb), f"{page}: a student's notebook stores no answer"
    using = (site / "using.html").read_text(encoding="utf-8")
    plain = re.sub(r"<[^>]+>", "", using)
    assert f'href="_static/downloads/{wheels[0].name}"' in using and f'pip install "{wheels[0].name}[book]"' in plain


def test_exercises_fold_their_answers_and_the_appendices_gather_them(site):
    answers = (site / "answers.html").read_text(encoding="utf-8")
    for page in CHAPTERS:
        html = (site / f"{page}.html").read_text(encoding="utf-8")
        if "exercise_section" not in (ROOT / "notebooks" / f"{page}.ipynb").read_text(encoding="utf-8"):
            continue  # chapters 9 and 12 get their cells at merge time
        assert "Learning objectives" in html and "Prerequisites" in html, page
        folded = re.findall(r'<details class="exercise-answer">\s*<summary>Worked answer (\d\d\.\d)</summary>', html)
        assert len(folded) >= (4 if int(page[:2]) <= 5 else 2), page
        for ex_id in folded:
            assert f"<strong>{ex_id}.</strong>" in answers, ex_id
    glossary = (site / "glossary.html").read_text(encoding="utf-8")
    assert "quality factor" in glossary and "damped natural frequency" in glossary
    assert "Running the chapters with other parameters" in (site / "symbols.html").read_text(encoding="utf-8")
    assert "CC BY 4.0" in (site / "licences.html").read_text(encoding="utf-8")


def test_front_page_marks_the_core_course_and_the_advanced_parts(site):
    front = (site / "index.html").read_text(encoding="utf-8")
    assert "Part I: the paper, reproduced and audited (core course)" in front
    assert "Part II: beyond the paper (advanced)" in front and "A suggested course" in front
    text = re.sub(r"<[^>]+>", "", front)
    for page in CHAPTERS[:11]:  # the contents: "N. Title: level: question?"
        level = "core" if int(page[:2]) <= 5 else "advanced"
        entries = [ln for ln in text.splitlines() if ln.strip().startswith(f"{int(page[:2])}. ") and f"{level}:" in ln]
        assert entries and entries[0].rstrip().endswith("?"), page
    assert "Authors, venue and year not stated" in (site / "references.html").read_text(encoding="utf-8")


def test_each_folded_run_of_a_notebook_is_one_closed_fold_of_its_page_with_no_section_inside(site):
    """The cells a chapter tags "details" (checks, convergence, secondary comparisons) leave its main text:
    one closed <details> per run of tagged cells (a tagged heading at the run's opening level or above
    opens the next), every tagged table and figure inside one, no heading."""
    import nbformat
    from bs4 import BeautifulSoup

    folded = 0
    for path in NOTEBOOKS:
        runs, opening = 0, None  # opening: the heading level the current fold opens with (0: none)
        for cell in nbformat.read(path, as_version=4).cells:
            if "details" not in cell.metadata.get("tags", []):
                opening = None
                continue
            head = re.match(r"(#{1,6}) ", cell.source.lstrip()) if cell.cell_type == "markdown" else None
            level = len(head[1]) if head else 0
            if opening is None or (opening and level and level <= opening):
                runs, opening = runs + 1, level  # a new run, or a section at the fold's own level
        page = site / ("index.html" if path.stem.startswith("00_") else f"{path.stem}.html")
        folds = BeautifulSoup(page.read_text(encoding="utf-8"), "html.parser").select("details.vib-details")
        assert len(folds) == runs, (path.stem, len(folds), runs)
        for fold in folds:
            assert fold.find("section") is None and fold.find(re.compile(r"^h[1-6]$")) is None, path.stem
            assert fold.find("summary").get_text().startswith("Details") and not fold.has_attr("open"), path.stem
        folded += runs
    assert folded >= 10  # the chapters of Part II fold their checks
