"""LaTeX to MathML at build time, and the URLs a page would fetch from outside itself.

The book renders every equation as MathML (browsers render it natively, so no MathJax
and no network); :func:`external_urls` lets tests and the builder check that a page
loads nothing from outside the build folder.
"""

from __future__ import annotations

import functools
import html
import re
from html.parser import HTMLParser

from latex2mathml.converter import convert as _latex2mathml

_ENV_ALIASES = {"aligned": "split", "equation": None, "equation*": None, "displaymath": None}


# A one-letter identifier of inline math: italic by a class, not by the browser's mapping to the Unicode
# mathematical italic letters, which only a math font has (the letter would drop out of the text's typeface).
_LETTER_MI = re.compile(r"<mi>(.|&#x[0-9A-Fa-f]+;)</mi>")

# |, / and \| are ordinary symbols in TeX; MathML would space them as infix operators.
_ORD_MO = re.compile(r"<mo((?: (?:stretchy|fence)=\"false\")*)>(&#x0007C;|&#x0002F;|&#x02016;)</mo>")


@functools.lru_cache(maxsize=4096)  # the pages and the search page's text convert each formula: once each
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

    Inline, a one-letter identifier carries the class ``vib-it`` (the stylesheet sets it italic in the text's
    own typeface); a name such as sin stays upright:

    >>> inline = latex_to_mathml(r"x\sin t", display=False)
    >>> inline.count('<mi class="vib-it">'), '<mi>sin</mi>' in inline
    (2, True)
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
    if not display:
        inner = _LETTER_MI.sub(r'<mi class="vib-it">\1</mi>', inner)
    annotation = html.escape(tex.strip(), quote=False)
    return (
        f'<math display="{mode}"><semantics><mrow>{inner}</mrow>'
        f'<annotation encoding="application/x-tex">{annotation}</annotation></semantics></math>'
    )


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
