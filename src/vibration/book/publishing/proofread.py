"""Proofreading the built book: what a reader sees, checked for code notation, repetition and alt text.

The checks read the HTML pages as a reader does (the article's text without code, maths,
scripts and the kernel-free panels' scripts) and report, per page:

* :func:`code_notation`: underscored code names (``x_ss``, ``omega_res``), e-notation
  (``1.2e+05``), ``^`` powers and ``sqrt(`` in the prose;
* :func:`repeated_paragraphs`: paragraphs, list items or table captions that appear twice on a
  page once every number is replaced by ``#`` (so a rounding difference does not hide a repeat);
* :func:`figures_without_alt`: images whose alt text is empty or a file name;
* :func:`sentences` of the main text (folds and exercises left out) and :func:`repeated_sentences`, the
  sentences of eight or more words said twice on a page.

Examples
--------
>>> code_notation("<main><p>The peak x_ss = 1.2e+05 m, 2^3 and sqrt(2).</p><code>x_ss</code></main>")
['x_ss', '1.2e+05', '2^3', 'sqrt(']
>>> repeated_paragraphs("<main><p>It is 1.25 m.</p><p>It is 1.3 m.</p><p>Other.</p></main>")
['It is 1.25 m.']
>>> said = "<main><p>The steady amplitude is 2.237 m at this forcing.</p><p>Short. "
>>> repeated_sentences(said + "The steady amplitude is 2.237 m at this forcing.</p></main>")
['The steady amplitude is 2.237 m at this forcing.']
"""

from __future__ import annotations

import re

from bs4 import BeautifulSoup

_SKIP = ["code", "pre", "math", "script", "style", "kbd", "samp", "svg", "canvas", "select", "option", "input",
         "button", "nav", "header", "footer"]  # fmt: skip
_UNDERSCORE = re.compile(r"(?<![\w/.-])[A-Za-zα-ωΑ-Ω][A-Za-z0-9α-ωΑ-Ω]*_[A-Za-z0-9α-ωΑ-Ω{]+")
_ENOTATION = re.compile(r"(?<![\w.])\d+(?:\.\d+)?[eE][+-]?\d+\b")
_CARET = re.compile(r"\S*\^\S*")
_SQRT = re.compile(r"sqrt\(")


def _article(html: str):
    soup = BeautifulSoup(html, "html.parser")
    root = soup.select_one("article.bd-article") or soup.select_one("main") or soup
    for tag in root.find_all(_SKIP):
        tag.decompose()
    for tag in root.select(".highlight, .headerlink, .vib-page-mark, .vib-print-note, .vib-footer, details > summary"):
        tag.decompose()
    return root


def code_notation(html: str) -> list[str]:
    """Code notation in the reader's text of one page (an empty list when there is none)."""
    text = _article(html).get_text(" ")
    found = []
    for pattern in (_UNDERSCORE, _ENOTATION, _CARET, _SQRT):
        found += [m.group(0) for m in pattern.finditer(text)]
    return found


def _normal(text: str) -> str:
    text = " ".join(text.split())
    return re.sub(r"[−-]?\d[\d.,]*(?:\s?×\s?10[⁻⁰¹²³⁴⁵⁶⁷⁸⁹]+)?", "#", text)


def repeated_paragraphs(html: str, shortest: int = 40) -> list[str]:
    """Paragraphs (and list items, captions, table cells of prose length) that appear twice on one page."""
    root = _article(html)
    seen: dict[str, str] = {}
    repeats = []
    for tag in root.find_all(["p", "li", "caption", "figcaption", "blockquote"]):
        if tag.find(["p", "li"]):  # containers: their own paragraphs are compared
            continue
        if tag.find_parent(["td", "th"]):  # table cells repeat by nature (units, case names)
            continue
        text = " ".join(tag.get_text(" ").split())
        if len(text) < shortest and tag.name != "p":
            continue
        if len(text) < 12:
            continue
        key = _normal(text)
        if key in seen and seen[key] not in repeats:
            repeats.append(seen[key])
        seen.setdefault(key, text)
    return repeats


def sentences(html: str, shortest: int = 8) -> list[str]:
    """The sentences of ``shortest`` or more words in a page's main text, in order: what a reader sees unfolded
    (folded details and the exercises left out, as the book's length limits count it)."""
    root = _article(html)
    for tag in root.select("details, section#exercises"):
        tag.decompose()
    text = " ".join(root.get_text(" ").split())
    return [s for s in re.split(r"(?<=[.!?])\s+", text) if len(s.split()) >= shortest]


def repeated_sentences(html: str, shortest: int = 8) -> list[str]:
    """Sentences of ``shortest`` or more words said twice in a page's main text (each once, in order)."""
    seen: set[str] = set()
    repeats: list[str] = []
    for sentence in sentences(html, shortest):
        if sentence in seen and sentence not in repeats:
            repeats.append(sentence)
        seen.add(sentence)
    return repeats


def figures_without_alt(html: str) -> list[str]:
    """Images (src) whose alt text is missing, empty or a file name."""
    soup = BeautifulSoup(html, "html.parser")
    bad = []
    for img in soup.select("article img, main img"):
        alt = (img.get("alt") or "").strip()
        if not alt or re.search(r"\.(png|svg|jpe?g|gif)\b|_images", alt) or re.fullmatch(r"[\w./\\-]+", alt):
            bad.append(img.get("src", "?"))
    return bad
