"""Search results with their text, also when the book is opened from disk.

Sphinx's search page shows under each result a few lines of the page around the words searched for; it
fetches the page to find them, and a browser refuses that fetch to a page opened from disk (``file://``).
So the build writes each page's text once more, section by section, into a script the search page loads
(``_static/vibration-search-pages.js``); the script answers the search page's request for a page from it
and leaves every other request to the browser. The search page alone loads the script.

The text is taken from the page's resolved document (code cells left out, tables and outputs as plain
text). Each page's part is kept beside the build's environment, so a build that rewrites only some pages
still writes every page's text.
"""

from __future__ import annotations

import html
import json
import re
from pathlib import Path

from docutils import nodes

from .mathml import latex_to_mathml

SCRIPT = "vibration-search-pages.js"
_TAGS = re.compile(r"<[^>]+>")
#: Tags inside a run of text (a subscript, a link, an emphasis): dropped without a space, "ω<sub>n</sub>" -> "ωn".
_INLINE_TAGS = re.compile(r"</?(?:sub|sup|span|a|em|strong|b|i|abbr|small|math|m[a-z]+)\b[^>]*>")
#: Code in raw HTML (a parameters table's column of option names) and a formula's TeX source are not a page's text.
_CODE = re.compile(r"<(code|annotation)\b[^>]*>.*?</\1>", re.S)


def _html_text(markup: str) -> str:
    """The text of an HTML fragment: code left out, inline tags dropped, block tags a space.

    >>> " ".join(_html_text('<p>ω<sub>n</sub> = 4.47 rad/s</p><td><code>omega</code></td><td>x</td>').split())
    'ωn = 4.47 rad/s x'
    """
    return html.unescape(_TAGS.sub(" ", _INLINE_TAGS.sub("", _CODE.sub("", markup))))


#: Nodes whose text is not part of a page's searchable text: code, figures' images and scripts.
_SKIP = (nodes.literal_block, nodes.image, nodes.comment, nodes.system_message)


def _is_code_input(node) -> bool:
    return isinstance(node, nodes.Element) and "cell_input" in node.get("classes", [])


def _text(node) -> str:
    """The visible text of ``node`` outside its subsections, raw HTML stripped of its tags."""
    if isinstance(node, _SKIP) or _is_code_input(node):
        return ""
    if isinstance(node, nodes.raw):
        return _html_text(node.astext()) if "html" in node.get("format", "") else ""
    if isinstance(node, (nodes.math, nodes.math_block)):  # the formula's characters, as the page shows them
        return _html_text(latex_to_mathml(node.astext(), display=isinstance(node, nodes.math_block)))
    if isinstance(node, nodes.Text):
        return str(node)
    inline = isinstance(node, (nodes.TextElement, nodes.Inline))  # a paragraph's words and links run on
    return ("" if inline else " ").join(_text(child) for child in node.children if not isinstance(child, nodes.section))


def section_html(section) -> str:
    """One section as nested ``<section id=…>`` elements holding its text (the search page's anchors).

    >>> s = nodes.section(ids=["damping"]); s += nodes.title(text="Damping"); s += nodes.paragraph(text="ζ < 1")
    >>> section_html(s)
    '<section id="damping">Damping ζ &lt; 1</section>'
    """
    ids = section.get("ids", [])
    inner = html.escape(" ".join(_text(section).split()), quote=False)  # its own text, subsections apart
    children = "".join(section_html(child) for child in section.children if isinstance(child, nodes.section))
    ident = f' id="{html.escape(ids[0])}"' if ids else ""
    return f"<section{ident}>{inner}{children}</section>"


def _store(app) -> Path:
    return Path(app.doctreedir) / "vibration-search-text"


def _keep_page_text(app, doctree, docname) -> None:
    """Keep the page's text (``doctree-resolved``), a part of the search page's script."""
    if app.builder.format != "html":
        return
    body = "".join(section_html(s) for s in doctree.children if isinstance(s, nodes.section))
    store = _store(app)
    store.mkdir(parents=True, exist_ok=True)
    (store / f"{docname.replace('/', '__')}.html").write_text(body, encoding="utf-8")


def script(pages: dict[str, str]) -> str:
    """The search page's script: each page's text, answering the search page's requests for pages.

    >>> print(script({"a.html": "<section>x</section>"}).splitlines()[0])
    const VIB_SEARCH_PAGES = {"a.html": "<div role=\\"main\\"><section>x</section></div>"};
    """
    wrapped = {name: f'<div role="main">{body}</div>' for name, body in sorted(pages.items())}
    return (
        f"const VIB_SEARCH_PAGES = {json.dumps(wrapped, ensure_ascii=False)};\n"
        "(() => {\n"
        "  const browserFetch = window.fetch.bind(window);\n"
        "  window.fetch = (url, ...rest) => {\n"
        "    const name = String(url).split('#')[0].split('?')[0].split('/').pop();\n"
        "    const page = VIB_SEARCH_PAGES[name];\n"
        "    return page === undefined ? browserFetch(url, ...rest)\n"
        "      : Promise.resolve(new Response(page, {headers: {'Content-Type': 'text/html'}}));\n"
        "  };\n"
        "})();\n"
    )


def _write_script(app, exception) -> None:
    """Write the search page's script from every current page's kept text (``build-finished``)."""
    if exception is not None or app.builder.format != "html":
        return
    found = set(app.env.found_docs)
    pages = {}
    for part in sorted(_store(app).glob("*.html")):
        docname = part.stem.replace("__", "/")
        if docname in found:
            pages[docname + app.builder.out_suffix] = part.read_text(encoding="utf-8")
    static = Path(app.outdir) / "_static"
    static.mkdir(parents=True, exist_ok=True)
    (static / SCRIPT).write_text(script(pages), encoding="utf-8")


def _load_on_search_page(app, pagename, templatename, context, doctree) -> None:
    """The search page alone loads the pages' text (``html-page-context``)."""
    if pagename == "search":
        app.add_js_file(SCRIPT)


def setup(app) -> None:
    app.connect("doctree-resolved", _keep_page_text)
    app.connect("build-finished", _write_script)
    app.connect("html-page-context", _load_on_search_page)
