"""Executed notebooks to self-contained, offline HTML.

nbconvert's ``lab`` template loads require.js, MathJax, Mermaid and the
ipywidgets manager from CDNs. :func:`render_notebook_html` uses the same
template with those script blocks emptied (template blocks
``html_head_js``, ``html_head_js_mathjax``, ``html_head_js_mermaidjs``,
``jupyter_widgets``), converts the LaTeX of markdown cells and ``text/latex``
outputs to MathML at build time with latex2mathml (browsers render MathML
natively), keeps figures as base64 ``data:`` URIs (nbconvert's default; images
referenced from markdown are embedded too) and replaces live-widget outputs,
whose state papermill does not save, by a short note. Mermaid diagrams stay as
their source text; credit comments holding URLs are dropped from the inlined
CSS. The page loads nothing: :func:`external_urls` lists what it would load, and
the tests check it is empty. Cells tagged ``remove-cell``, ``remove-input`` or
``remove-output`` lose that part.

Where ``extra_html`` goes: if the rendered page contains the marker
:data:`EXTRA_HTML_MARKER` (``<!-- vibration:extra-html -->``, written on a line of
its own in a markdown cell), the first marker is replaced by ``extra_html``;
otherwise ``extra_html`` is appended at the end of the page body (just before
``</main>``).
"""

from __future__ import annotations

import copy
import html
import re
from html.parser import HTMLParser
from importlib.resources import files
from pathlib import Path

import jinja2
import nbformat
from jinja2 import pass_context
from latex2mathml.converter import convert as _latex2mathml
from nbconvert.exporters import HTMLExporter
from nbconvert.filters.markdown_mistune import IPythonRenderer, MarkdownWithMath

#: Marker that, placed alone on a line of a markdown cell, receives ``extra_html``.
EXTRA_HTML_MARKER = "<!-- vibration:extra-html -->"

#: MIME type of a live ipywidget view (its model state is lost after papermill).
WIDGET_VIEW_MIMETYPE = "application/vnd.jupyter.widget-view+json"

#: Cell tags that drop a whole cell, its input or its output from the page.
REMOVE_CELL_TAGS = ("remove-cell", "remove_cell")
REMOVE_INPUT_TAGS = ("remove-input", "remove_input", "hide-input")
REMOVE_OUTPUT_TAGS = ("remove-output", "remove_output", "hide-output")

_TEMPLATE_NAME = "vibration_static.html.j2"
_TEMPLATE = r"""{%- extends 'index.html.j2' -%}
{#- No script from a CDN: require.js, MathJax, Mermaid and the widget manager are left out. -#}
{%- block html_head_js -%}{%- endblock html_head_js -%}
{%- block jupyter_widgets -%}{%- endblock jupyter_widgets -%}
{%- block html_head_js_mathjax -%}{%- endblock html_head_js_mathjax -%}
{%- block html_head_js_mermaidjs -%}{%- endblock html_head_js_mermaidjs -%}
{%- block html_head_css -%}
<style type="text/css">
{{ resources.vibration_css }}
</style>
{%- endblock html_head_css -%}
{%- block data_latex scoped -%}
<div class="jp-RenderedLatex jp-OutputArea-output {{ extra_class }}" data-mime-type="text/latex">
{{ output.data['text/latex'] | markdown2html }}
</div>
{%- endblock data_latex -%}
{%- block data_widget_view scoped -%}{%- endblock data_widget_view -%}
"""


def _css() -> str:
    return files("vibration.presentation").joinpath("assets", "report.css").read_text(encoding="utf-8")


# --------------------------------------------------------------------------- math


_ENV_ALIASES = {"aligned": "split", "equation": None, "equation*": None, "displaymath": None}


# |, / and \| are ordinary symbols in TeX; MathML would space them as infix operators.
_ORD_MO = re.compile(r"<mo((?: (?:stretchy|fence)=\"false\")*)>(&#x0007C;|&#x0002F;|&#x02016;)</mo>")


def latex_to_mathml(tex: str, display: bool) -> str:
    r"""MathML for one LaTeX formula, with the source kept as an annotation.

    ``aligned`` is rewritten as ``split`` (same layout; latex2mathml knows only
    the latter) and the ``equation``/``equation*``/``displaymath`` wrappers are
    dropped. A formula latex2mathml cannot parse is shown as its TeX source in a
    ``<code class="vib-tex-fallback">``, so nothing silently disappears.

    Parameters
    ----------
    tex : str
        The formula without its ``$``/``$$`` delimiters.
    display : bool
        Display (block) math rather than inline math.

    Returns
    -------
    str
        ``<math display="block|inline">`` with ``<semantics>`` and a TeX annotation.

    Examples
    --------
    >>> latex_to_mathml(r"\omega_n", display=False)[:40]
    '<math display="inline"><semantics><mrow>'
    """
    body = tex.strip()
    for env, alias in _ENV_ALIASES.items():
        pattern = re.escape(env)
        if alias is None:
            wrapped = rf"^\\begin\{{{pattern}\}}(.*)\\end\{{{pattern}\}}$"
            body = re.sub(wrapped, r"\1", body, flags=re.S).strip()
        else:
            body = body.replace(rf"\begin{{{env}}}", rf"\begin{{{alias}}}")
            body = body.replace(rf"\end{{{env}}}", rf"\end{{{alias}}}")
    mode = "block" if display else "inline"
    try:
        mathml = _latex2mathml(body, display=mode)
    except Exception:  # latex2mathml raises assorted errors on what it does not support
        delim = "$$" if display else "$"
        return f'<code class="vib-tex-fallback">{html.escape(delim + tex + delim)}</code>'
    inner = mathml[mathml.index(">") + 1 : mathml.rindex("</math>")]
    inner = _ORD_MO.sub(r'<mo\1 lspace="0em" rspace="0em">\2</mo>', inner)
    annotation = html.escape(tex.strip(), quote=False)
    return (
        f'<math display="{mode}"><semantics><mrow>{inner}</mrow>'
        f'<annotation encoding="application/x-tex">{annotation}</annotation></semantics></math>'
    )


class MathMLRenderer(IPythonRenderer):
    """nbconvert's markdown renderer with math written as MathML instead of left for MathJax."""

    def block_math(self, body: str) -> str:
        """``$$ ... $$`` and ``\\[ ... \\]``."""
        return latex_to_mathml(body, display=True)

    def inline_math(self, body: str) -> str:
        """``$ ... $`` and ``\\( ... \\)``."""
        return latex_to_mathml(body, display=False)

    def latex_environment(self, name: str, body: str) -> str:
        """``\\begin{name} ... \\end{name}`` outside dollars."""
        return latex_to_mathml(f"\\begin{{{name}}}{body}\\end{{{name}}}", display=True)


class OfflineHTMLExporter(HTMLExporter):
    """``HTMLExporter`` (lab template) whose pages load nothing from the network.

    See the module docstring for what is removed and how math is rendered.
    """

    @pass_context
    def markdown2html(self, context, source):
        """Markdown to HTML with MathML math (same options as nbconvert's filter)."""
        cell = context.get("cell", {})
        path = context.get("resources", {}).get("metadata", {}).get("path", "")
        renderer = MathMLRenderer(
            escape=False,
            attachments=cell.get("attachments", {}),
            embed_images=self.embed_images,
            path=path,
            anchor_link_text=self.anchor_link_text,
            exclude_anchor_links=self.exclude_anchor_links,
            **self.lexer_options,
        )
        return MarkdownWithMath(renderer=renderer).render(source)


def _exporter() -> OfflineHTMLExporter:
    from traitlets.config import Config

    cfg = Config()
    cfg.TagRemovePreprocessor.enabled = True
    cfg.TagRemovePreprocessor.remove_cell_tags = set(REMOVE_CELL_TAGS)
    cfg.TagRemovePreprocessor.remove_input_tags = set(REMOVE_INPUT_TAGS)
    cfg.TagRemovePreprocessor.remove_all_outputs_tags = set(REMOVE_OUTPUT_TAGS)
    exporter = OfflineHTMLExporter(
        config=cfg,
        template_name="lab",
        extra_loaders=[jinja2.DictLoader({_TEMPLATE_NAME: _TEMPLATE})],
        embed_images=True,
    )
    exporter.template_file = _TEMPLATE_NAME
    return exporter


# ------------------------------------------------------------------------ widgets


def _widget_note(has_panel: bool) -> dict:
    text = "Interactive widget: it needs a running Jupyter kernel and is not part of this static page."
    if has_panel:
        text += " The slider panel on this page computes the same response in the browser."
    return nbformat.v4.new_output(
        "display_data",
        data={"text/html": f'<div class="vib-widget-note">{html.escape(text)}</div>', "text/plain": text},
    )


def strip_widgets(nb: nbformat.NotebookNode, *, has_panel: bool = False) -> nbformat.NotebookNode:
    """Copy of ``nb`` without live-widget outputs or saved widget state.

    An output that carries a widget view and another rich representation
    (ipympl's PNG, say) keeps that representation; an output that has only the
    widget view and its ``text/plain`` repr (``VBox(...)``) becomes one short note
    per cell.

    Parameters
    ----------
    nb : nbformat.NotebookNode
        An executed notebook (left unchanged).
    has_panel : bool
        Whether the page carries a static slider panel (changes the note's wording).

    Returns
    -------
    nbformat.NotebookNode
    """
    nb = copy.deepcopy(nb)
    nb.metadata.pop("widgets", None)
    for cell in nb.cells:
        if cell.cell_type != "code":
            continue
        outputs = []
        for out in cell.get("outputs", []):
            data = out.get("data", {})
            if WIDGET_VIEW_MIMETYPE not in data:
                outputs.append(out)
                continue
            del data[WIDGET_VIEW_MIMETYPE]
            if any(mime != "text/plain" for mime in data):
                data.pop("text/plain", None)
                outputs.append(out)
            elif not (outputs and outputs[-1].get("metadata", {}).get("vibration_widget_note")):
                note = _widget_note(has_panel)
                note.metadata["vibration_widget_note"] = True
                outputs.append(note)
        cell.outputs = outputs
    return nb


# ------------------------------------------------------------------------- render


_STYLE_BLOCK = re.compile(r"<style\b[^>]*>.*?</style>", re.S | re.I)
_CSS_URL_COMMENT = re.compile(r"/\*(?:(?!\*/).)*?https?://.*?\*/", re.S)  # credits in nbconvert's CSS


def _first_heading(nb: nbformat.NotebookNode) -> str | None:
    for cell in nb.cells:
        if cell.cell_type == "markdown":
            for line in cell.source.splitlines():
                m = re.match(r"#\s+(.+?)\s*#*\s*$", line)
                if m:
                    return re.sub(r"\$([^$]*)\$", r"\1", m.group(1))
    return None


def render_notebook_html(
    nb_path_or_node,
    out_path,
    *,
    title: str | None = None,
    extra_html: str = "",
) -> Path:
    """Write one executed notebook as a single self-contained HTML file.

    The page shows every markdown cell (equations as MathML), every code cell
    with its outputs and every figure (base64 PNG); it loads no script, style,
    font or image from anywhere, so it works from disk with no network and no
    kernel. Live-widget outputs become a short note (see :func:`strip_widgets`);
    cells tagged ``remove-cell``, ``remove-input`` or ``remove-output`` lose
    that part.

    Parameters
    ----------
    nb_path_or_node : str, os.PathLike or nbformat.NotebookNode
        The executed notebook (``.ipynb`` path or node; a node is not modified).
        Images linked from markdown are embedded from the notebook's folder: for
        a node, papermill's ``metadata.papermill.input_path`` folder, else the cwd.
    out_path : str or os.PathLike
        The HTML file to write; its folder is created if needed.
    title : str, optional
        Page title; default: the notebook's first ``# heading``, else the file stem.
    extra_html : str
        HTML placed at :data:`EXTRA_HTML_MARKER` if the page has one, else at
        the end of the body (e.g. :func:`vibration.presentation.static_page.slider_panel_html`).

    Returns
    -------
    pathlib.Path
        ``out_path``.
    """
    out_path = Path(out_path)
    if isinstance(nb_path_or_node, nbformat.NotebookNode):
        nb, stem = nb_path_or_node, out_path.stem
        input_path = nb.metadata.get("papermill", {}).get("input_path")  # set by papermill
        src_dir = Path(input_path).parent if input_path else Path.cwd()
    else:
        src = Path(nb_path_or_node)
        nb, src_dir, stem = nbformat.read(src, as_version=4), src.parent, src.stem
    nb = strip_widgets(nb, has_panel=bool(extra_html))
    nb.metadata["title"] = title or _first_heading(nb) or stem
    resources = {
        "metadata": {"name": stem, "path": str(src_dir)},
        "vibration_css": _css(),
    }
    body, _ = _exporter().from_notebook_node(nb, resources=resources)
    body = _STYLE_BLOCK.sub(lambda m: _CSS_URL_COMMENT.sub("", m.group(0)), body)
    if extra_html:
        if EXTRA_HTML_MARKER in body:
            body = body.replace(EXTRA_HTML_MARKER, extra_html, 1)
        else:
            head, sep, tail = body.rpartition("</main>")
            if not sep:
                head, sep, tail = body.rpartition("</body>")
            body = f"{head}{extra_html}\n{sep}{tail}"
    out_path.parent.mkdir(parents=True, exist_ok=True)
    out_path.write_text(body, encoding="utf-8")
    return out_path


# -------------------------------------------------------------------------- index


def write_index_html(out_path, chapters: list[dict], *, title: str = "Forced mass-spring-damper: report") -> Path:
    """Write an index page that links the rendered chapters (same CSS, no external URL).

    Parameters
    ----------
    out_path : str or os.PathLike
        The HTML file to write; its folder is created if needed.
    chapters : list of dict
        One dict per chapter with ``title`` (str), ``href`` (str, relative link),
        ``summary`` (str, plain text) and ``elapsed_s`` (float, execution time in s,
        or None).
    title : str
        Page title and heading.

    Returns
    -------
    pathlib.Path
        ``out_path``.
    """
    e = html.escape
    items = []
    for ch in chapters:
        elapsed = ch.get("elapsed_s")
        run = ""
        if elapsed is not None:
            run = f'<span class="vib-elapsed">executed in {float(elapsed):.1f} s</span>'

        items.append(
            f'<li><a class="vib-chapter" href="{e(str(ch["href"]))}">{e(str(ch["title"]))}</a>{run}'
            f'<p class="vib-summary">{e(str(ch.get("summary", "")))}</p></li>'
        )
    page = f"""<!DOCTYPE html>
<html lang="en">
<head>
<meta charset="utf-8">
<meta name="viewport" content="width=device-width, initial-scale=1.0">
<title>{e(title)}</title>
<style type="text/css">
{_css()}</style>
</head>
<body class="vib-report">
<main>
<h1>{e(title)}</h1>
<p class="vib-lead">Each chapter is one executed notebook rendered as a self-contained page: it opens
from disk, with no network and no Jupyter kernel.</p>
<ol class="vib-chapters">
{chr(10).join(items)}
</ol>
<footer>Rebuild with <code>make report</code>.</footer>
</main>
</body>
</html>
"""
    out_path = Path(out_path)
    out_path.parent.mkdir(parents=True, exist_ok=True)
    out_path.write_text(page, encoding="utf-8")
    return out_path


# ---------------------------------------------------------------- URL inspection

_URL_ATTRS = {"src", "href", "srcset", "data", "poster", "action", "formaction", "background", "xlink:href"}
_CSS_URL = re.compile(r"""url\(\s*(['"]?)(.*?)\1\s*\)|@import\s+(['"])(.*?)\3""", re.I | re.S)


def _is_external(url: str) -> bool:
    u = url.strip()
    if not u or u.startswith("#"):
        return False
    if u[:5].lower() == "data:":
        return False
    if u.startswith("//"):
        return True
    return re.match(r"[A-Za-z][A-Za-z0-9+.-]*:", u) is not None  # any other scheme: http, file, ...


class _URLCollector(HTMLParser):
    def __init__(self) -> None:
        super().__init__(convert_charrefs=True)
        self.urls: list[str] = []
        self._in_style = False

    def handle_starttag(self, tag, attrs):
        for name, value in attrs:
            if value is None:
                continue
            if name in _URL_ATTRS:
                if name == "srcset":  # "url 2x, url 480w, ..."
                    self.urls.extend(p.split()[0] for p in value.split(",") if p.strip())
                else:
                    self.urls.append(value)
            elif name == "style":
                self._css(value)
        self._in_style = tag == "style"

    def handle_endtag(self, tag):
        if tag == "style":
            self._in_style = False

    def handle_data(self, data):
        if self._in_style:
            self._css(data)

    def _css(self, text: str) -> None:
        text = re.sub(r"/\*.*?\*/", "", text, flags=re.S)  # URLs in CSS comments load nothing
        for m in _CSS_URL.finditer(text):
            self.urls.append(m.group(2) if m.group(2) is not None else m.group(4))


def external_urls(html_text: str) -> list[str]:
    """URLs a page would fetch from outside itself.

    Looks at ``src``, ``href``, ``srcset``, ``data``, ``poster``, ``action`` and
    ``xlink:href`` attributes and at ``url(...)``/``@import`` in ``<style>`` and
    ``style=""``; returns those that are not ``data:`` URIs, relative paths or
    ``#`` anchors, in document order.

    Parameters
    ----------
    html_text : str
        An HTML document or fragment.

    Returns
    -------
    list of str

    Examples
    --------
    >>> external_urls('<img src="data:image/png;base64,AA=="><a href="#s1">s</a><a href="ch1.html">1</a>')
    []
    >>> external_urls('<script src="https://cdn.ex/x.js"></script><style>@import "//f.ex/a.css";</style>')
    ['https://cdn.ex/x.js', '//f.ex/a.css']
    """
    parser = _URLCollector()
    parser.feed(html_text)
    parser.close()
    return [u for u in parser.urls if _is_external(u)]
