"""The live explorers in a real JupyterLab, driven by headless Chromium.

Starts ``jupyter lab`` from the project's virtual environment on a free port with a
random token, on a temporary copy of ``notebooks/``, with its own settings,
workspaces, config and runtime folders (news, update checks and the extension
manager off; notebook windowing off so that every cell is in the page). Every
notebook whose source uses chapter 5's live explorer (``vibration.book.chapters.explore.widget``)
is opened, run with *Run All Cells*, and each explorer in it is exercised: both sliders moved with the
keyboard, a bad mass typed; the readout and the figure must change, and no
output may show a traceback. Screenshots go to ``build/screenshots/``.
"""

from __future__ import annotations

import hashlib
import json
import os
import re
import secrets
import shutil
import signal
import socket
import subprocess
import sys
import time
import urllib.error
import urllib.request
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
NOTEBOOKS = ROOT / "notebooks"
JUPYTER = Path(sys.executable).parent / "jupyter"
SCREENSHOTS = ROOT / "build" / "screenshots"
KERNEL_DISPLAY_NAME = "Python 3 (vibration)"
USES_WIDGETS = re.compile(
    r"vibration\.book\.chapters\.explore\.widget\b|from\s+vibration\.book\.chapters\.explore\s+import\s+[^\n]*\bwidget\b"
    r"|from\s+vibration\.book\.chapters\.explore\.panel\s+import\s+[^\n]*\bpanel\b"  # panel(study): the live explorer
)

#: JupyterLab settings for a quiet, deterministic session.
LAB_SETTINGS = {
    "@jupyterlab/notebook-extension/tracker.jupyterlab-settings": {"windowingMode": "none"},
    "@jupyterlab/apputils-extension/notification.jupyterlab-settings": {
        "fetchNews": "false",
        "checkForUpdates": False,
    },
    "@jupyterlab/extensionmanager-extension/plugin.jupyterlab-settings": {"enabled": False},
}

SERVER_START_S = 90  # until /api/status answers
RUN_ALL_S = 240  # until every cell of a notebook has run
UPDATE_S = 20  # until a widget reflects a slider move


def widget_notebooks(folder: Path) -> list[str]:
    """Names of the notebooks in ``folder`` whose code cells use ``vibration.book.chapters.explore.widget`` (directly or
    through the chapter's ``panel``)."""
    names = []
    for path in sorted(folder.glob("*.ipynb")):
        cells = json.loads(path.read_text(encoding="utf-8"))["cells"]
        code = "\n".join("".join(c["source"]) for c in cells if c["cell_type"] == "code")
        if USES_WIDGETS.search(code):
            names.append(path.name)
    return names


def _free_port() -> int:
    with socket.socket(socket.AF_INET, socket.SOCK_STREAM) as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def _get(url: str, timeout: float = 5.0) -> int:
    with urllib.request.urlopen(url, timeout=timeout) as resp:  # noqa: S310 - local server
        return resp.status


@pytest.fixture(scope="module")
def lab(tmp_path_factory):
    """A running JupyterLab on a copy of notebooks/: yields (base_url, token, root_dir)."""
    tmp = tmp_path_factory.mktemp("lab")
    root = tmp / "notebooks"
    shutil.copytree(NOTEBOOKS, root, ignore=shutil.ignore_patterns(".ipynb_checkpoints"))
    settings = tmp / "settings"
    for name, value in LAB_SETTINGS.items():
        path = settings / name
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(json.dumps(value), encoding="utf-8")
    env = dict(os.environ)
    env.update(
        JUPYTERLAB_SETTINGS_DIR=str(settings),
        JUPYTERLAB_WORKSPACES_DIR=str(tmp / "workspaces"),
        JUPYTER_CONFIG_DIR=str(tmp / "config"),
        JUPYTER_RUNTIME_DIR=str(tmp / "runtime"),
        PYTHONUNBUFFERED="1",
    )
    port, token = _free_port(), secrets.token_hex(24)
    base = f"http://127.0.0.1:{port}"
    log = (tmp / "server.log").open("wb")
    cmd = [
        str(JUPYTER), "lab", "--no-browser",
        "--ServerApp.ip=127.0.0.1", f"--ServerApp.port={port}", "--ServerApp.port_retries=0",
        f"--IdentityProvider.token={token}", f"--ServerApp.root_dir={root}",
        "--LabApp.news_url=", "--LabApp.check_for_updates_class=jupyterlab.NeverCheckForUpdate",
        "--LabApp.extension_manager=readonly",
    ]  # fmt: skip
    if os.geteuid() == 0:  # containers often run as root; the server refuses that unless told
        cmd.append("--allow-root")
    proc = subprocess.Popen(cmd, env=env, stdout=log, stderr=subprocess.STDOUT, start_new_session=True)
    try:
        deadline = time.monotonic() + SERVER_START_S
        while True:
            if proc.poll() is not None:
                raise RuntimeError(f"jupyter lab exited with {proc.returncode}:\n{_tail(tmp / 'server.log')}")
            try:
                if _get(f"{base}/api/status?token={token}") == 200:
                    break
            except (urllib.error.URLError, ConnectionError, TimeoutError):
                pass
            if time.monotonic() > deadline:
                raise RuntimeError(f"jupyter lab did not answer in {SERVER_START_S} s:\n{_tail(tmp / 'server.log')}")
            time.sleep(0.5)
        yield base, token, root
    finally:
        _shutdown(proc, base, token)
        log.close()


def _tail(path: Path, n: int = 40) -> str:
    return "\n".join(path.read_text(errors="replace").splitlines()[-n:])


def _shutdown(proc: subprocess.Popen, base: str, token: str) -> None:
    """Ask the server to stop (it shuts its kernels down), then terminate our process group if needed."""
    if proc.poll() is None:
        try:
            req = urllib.request.Request(f"{base}/api/shutdown?token={token}", method="POST")
            urllib.request.urlopen(req, timeout=10).close()  # noqa: S310 - local server
        except (urllib.error.URLError, ConnectionError, TimeoutError):
            pass
    try:
        proc.wait(timeout=20)
    except subprocess.TimeoutExpired:
        os.killpg(proc.pid, signal.SIGTERM)
        try:
            proc.wait(timeout=10)
        except subprocess.TimeoutExpired:
            os.killpg(proc.pid, signal.SIGKILL)
            proc.wait(timeout=10)


def _digest(png: bytes) -> str:
    return hashlib.sha256(png).hexdigest()


def _wait_for(predicate, timeout: float, what: str, interval: float = 0.2):
    deadline = time.monotonic() + timeout
    while True:
        value = predicate()
        if value:
            return value
        if time.monotonic() > deadline:
            raise AssertionError(f"timed out after {timeout} s waiting for {what}")
        time.sleep(interval)


def _choose_kernel_if_asked(page) -> None:
    dialog = page.locator(".jp-Dialog")
    if dialog.count() and "kernel" in dialog.inner_text().lower():
        dialog.locator("select").select_option(label=KERNEL_DISPLAY_NAME)
        dialog.locator("button.jp-mod-accept").click()


def _menu(page, menu: str, item: str) -> None:
    page.locator(".lm-MenuBar-itemLabel", has_text=re.compile(rf"^{menu}$")).click()
    page.locator(".lm-Menu-itemLabel", has_text=re.compile(rf"^{item}$")).click()


def _kernel_idle(page) -> bool:
    _choose_kernel_if_asked(page)
    status = page.locator(".jp-Notebook-ExecutionIndicator").first.get_attribute("data-status")
    return status == "idle" and page.get_by_text(f"{KERNEL_DISPLAY_NAME} | Idle").count() > 0


def _run_all(page, n_code: int) -> None:
    """Clear the stored outputs, run every cell, and wait until all have run (or one failed)."""
    _menu(page, "Edit", "Clear Outputs of All Cells")
    _wait_for(
        lambda: not any(re.search(r"\d", p) for p in page.locator(".jp-CodeCell .jp-InputPrompt").all_inner_texts()),
        UPDATE_S,
        "the stored outputs to be cleared",
    )
    _menu(page, "Run", "Run All Cells")

    def done():
        prompts = page.locator(".jp-CodeCell .jp-InputPrompt").all_inner_texts()
        counted = [p for p in prompts if re.fullmatch(r"\[\d+\]:", p.strip())]
        failed = page.locator('.jp-OutputArea-output[data-mime-type="application/vnd.jupyter.stderr"]').count()
        return _kernel_idle(page) and "[*]:" not in prompts and (len(counted) == n_code or failed > 0)

    _wait_for(done, RUN_ALL_S, "Run All Cells to finish", interval=0.5)
    errors = _errors_in_outputs(page)
    assert errors == [], "a cell failed under Run All Cells:\n" + "\n".join(errors)


def _errors_in_outputs(page) -> list[str]:
    texts = page.locator('.jp-RenderedText[data-mime-type="application/vnd.jupyter.stderr"]').all_inner_texts()
    bad = [t for t in texts if "Traceback" in t or "Error" in t]
    bad += [t for t in page.locator(".jp-OutputArea-output").all_inner_texts() if "Error displaying widget" in t]
    return bad


def _image_state(explorer) -> tuple[str, str]:
    img = explorer.locator(".vibration-figure img, img.vibration-figure").first
    return img.get_attribute("src") or "", _digest(img.screenshot())


def _move_slider(page, explorer, index: int, presses: int = 3) -> None:
    handle = explorer.locator(".widget-slider .noUi-handle, .noUi-handle").nth(index)
    handle.focus()
    for _ in range(presses):
        page.keyboard.press("ArrowRight")


def _exercise(page, explorer, shot: Path | None) -> dict:
    """Move each slider of one explorer and type a bad mass; return what was observed."""
    readout = explorer.locator(".vibration-readout")
    seen = {}
    n_sliders = explorer.locator(".noUi-handle").count()
    assert n_sliders == 2, f"expected the frequency and damping sliders, found {n_sliders}"
    for i, name in enumerate(("omega", "c")):
        text0 = readout.inner_text()
        src0, shot0 = _image_state(explorer)
        _move_slider(page, explorer, i)
        _wait_for(lambda t=text0: readout.inner_text() != t, UPDATE_S, f"the readout to follow the {name} slider")
        _wait_for(lambda s=src0: _image_state(explorer)[0] != s, UPDATE_S, f"a new image after the {name} slider")
        src1, shot1 = _image_state(explorer)
        assert shot1 != shot0, f"the figure's pixels did not change with the {name} slider"
        seen[name] = (text0, readout.inner_text())
    if shot is not None:
        shot.parent.mkdir(parents=True, exist_ok=True)
        explorer.scroll_into_view_if_needed()
        page.screenshot(path=str(shot))
    m_input = explorer.locator(".widget-text", has_text="m (kg)").locator("input")
    m_input.fill("0")
    m_input.press("Enter")
    _wait_for(lambda: "Input rejected" in readout.inner_text(), UPDATE_S, "the readout to reject m = 0")
    seen["m=0"] = readout.inner_text()
    m_input.fill("1")
    m_input.press("Enter")
    _wait_for(lambda: "Input rejected" not in readout.inner_text(), UPDATE_S, "the readout to accept m = 1")
    return seen


#: A MyST role as written in a notebook's Markdown ({numref}`tab-...`, {sub}`0`): JupyterLab's own renderer shows
#: the braces as text; with the MyST extension the role is rendered.
MYST_ROLE = re.compile(r"\{(?:numref|ref|eq|doc|term|sub|sup|math|cite|abbr)\}")
#: Notebooks whose Markdown cells use roles (chapter 7's outputs refer to its tables and figures too; chapter 4's
#: prose is all in its cells).
ROLES_NOTEBOOKS = ("04_frequency_response.ipynb", "07_control.ipynb")


def _markdown_sources(path: Path) -> tuple[list[str], list[str]]:
    """The Markdown cells' sources and the code cells' outputs whose only rich form is Markdown, of a notebook."""
    cells = json.loads(path.read_text(encoding="utf-8"))["cells"]
    own = ["".join(c["source"]) for c in cells if c["cell_type"] == "markdown"]
    outputs = [
        "".join(o["data"]["text/markdown"])
        for c in cells
        if c["cell_type"] == "code"
        for o in c.get("outputs", [])
        if set(o.get("data", {})) - {"text/plain"} == {"text/markdown"}  # with HTML beside it, JupyterLab shows that
    ]
    return own, outputs


#: A cross-reference in a notebook's Markdown: {numref}`fig-x` or {numref}`Figure 4.1 <fig-x>`.
NUMREF = re.compile(r"\{numref\}`(?:[^`<]*<)?(?P<label>[^`<>]+)>?`")
#: What JupyterLab's MyST renderer shows for a reference whose target it cannot find (as a tooltip; the text is
#: the label itself).
NOT_FOUND = "Cross Reference Not Found"


def _numbers(path: Path, chapter: int) -> dict[str, str]:
    """Label -> "Figure 4.1" / "Table 4.2": the book's numbering, counted here from the notebook's outputs in order
    (a figure carries its label in the output's metadata, a table in its Markdown's ``:name:`` line)."""
    cells = json.loads(path.read_text(encoding="utf-8"))["cells"]
    found, counts = {}, {"Figure": 0, "Table": 0}
    for c in cells:
        for o in c.get("outputs", []) if c["cell_type"] == "code" else []:
            labels = []
            figure = o.get("metadata", {}).get("vibration/figure")
            if figure:
                labels.append(("Figure", figure["name"]))
            labels += [
                ("Table", n)
                for n in re.findall(r"^:name: (\S+)", "".join(o.get("data", {}).get("text/markdown", "")), re.M)
            ]
            for kind, label in labels:
                counts[kind] += 1
                found[label] = f"{kind} {chapter}.{counts[kind]}"
    return found


def test_some_notebook_uses_the_widgets():
    assert "05_explore.ipynb" in widget_notebooks(NOTEBOOKS)


@pytest.mark.browser
@pytest.mark.slow
@pytest.mark.timeout(300)
@pytest.mark.parametrize("name", widget_notebooks(NOTEBOOKS))
def test_explorers_run_and_respond_in_jupyterlab(lab, browser, name):
    base, token, root = lab
    n_code = sum(c["cell_type"] == "code" for c in json.loads((root / name).read_text())["cells"])
    page = browser.new_page(viewport={"width": 1400, "height": 1300})
    page_errors = []
    page.on("pageerror", lambda exc: page_errors.append(str(exc)))
    try:
        # a fresh workspace per notebook: only this notebook is open, and menu commands act on it
        workspace = re.sub(r"\W", "-", Path(name).stem)
        page.goto(f"{base}/lab/workspaces/{workspace}/tree/{name}?reset&token={token}", wait_until="domcontentloaded")
        panel = page.locator(".jp-NotebookPanel").first
        panel.wait_for(timeout=60_000)
        assert page.locator(".jp-NotebookPanel").count() == 1
        panel.locator(".jp-Cell").first.click()
        _wait_for(
            lambda: (
                (_choose_kernel_if_asked(page) or True)
                and page.locator(".jp-Notebook-ExecutionIndicator").first.get_attribute("data-status") == "idle"
            ),
            90,
            "the kernel to start",
            interval=0.5,
        )
        _run_all(page, n_code)
        explorers = page.locator(".vibration-explorer")
        explorers.first.wait_for(timeout=30_000)
        n = explorers.count()
        assert n >= 1
        for i in range(n):
            shot = SCREENSHOTS / f"jupyterlab_{Path(name).stem}{'' if i == 0 else f'_{i}'}.png"
            seen = _exercise(page, explorers.nth(i), shot)
            assert "forcing frequency" in seen["omega"][1] and "rad/s" in seen["omega"][1]
            assert "m = 0.0 kg is out of range" in seen["m=0"]
        assert _errors_in_outputs(page) == []
        assert page_errors == [], page_errors
    except BaseException:
        SCREENSHOTS.mkdir(parents=True, exist_ok=True)
        page.screenshot(path=str(SCREENSHOTS / f"jupyterlab_{Path(name).stem}_failure.png"))
        raise
    finally:
        page.close()


@pytest.mark.browser
@pytest.mark.slow
@pytest.mark.timeout(300)
@pytest.mark.parametrize("name", ROLES_NOTEBOOKS)
def test_jupyterlab_renders_the_myst_roles_of_cells_and_outputs(lab, browser, name):
    """Opened (not run), a chapter's Markdown cells and stored Markdown outputs show no role's raw braces, and
    every cross-reference reads as a number or words, never as its label or "not found"."""
    base, token, root = lab
    own, outputs = _markdown_sources(root / name)
    assert sum(len(MYST_ROLE.findall(t)) for t in own) > 0  # and any stored Markdown output is checked below
    page = browser.new_page(viewport={"width": 1400, "height": 1300})
    try:
        page.goto(
            f"{base}/lab/workspaces/roles-{name[:2]}/tree/{name}?reset&token={token}", wait_until="domcontentloaded"
        )
        panel = page.locator(".jp-NotebookPanel").first
        panel.wait_for(timeout=60_000)
        cells = panel.locator(".jp-MarkdownCell .jp-Cell-inputWrapper")
        shown = panel.locator('.jp-OutputArea-output[data-mime-type="text/markdown"]')

        def rendered():  # every cell and output on the page, each with text (rendering is asynchronous)
            texts = cells.all_inner_texts() + shown.all_inner_texts()
            return len(texts) == len(own) + len(outputs) and all(t.strip() for t in texts) and texts

        texts = _wait_for(rendered, 60, "the Markdown cells and outputs to render", interval=0.5)
        raw = [m.group(0) + t[m.end() : m.end() + 40] for t in texts for m in MYST_ROLE.finditer(t)]
        assert raw == [], f"{len(raw)} MyST roles shown raw in {name}: {raw[:5]}"
        # every cross-reference of the Markdown cells reads as the book numbers it ("Figure 4.1"), none as its label
        # or as the renderer's "not found"
        numbers = _numbers(root / name, int(name[:2]))
        labels = [m.group("label") for t in own for m in NUMREF.finditer(t)]
        assert len(labels) >= 2 and set(labels) <= set(numbers), set(labels) - set(numbers)
        not_found = panel.locator(f'[title="{NOT_FOUND}"]').all_inner_texts()
        assert not_found == [], f"{len(not_found)} references not found in {name}: {not_found[:5]}"
        shown_text = "\n".join(cells.all_inner_texts())
        assert NOT_FOUND not in shown_text
        assert [label for label in labels if label in shown_text] == []  # a label shown as text
        said = "\n".join(shown.all_inner_texts())
        out_labels = {m.group("label") for t in outputs for m in NUMREF.finditer(t)}
        assert [label for label in out_labels if label in said] == []  # an output's label shown as text
        missing = [numbers[label] for label in labels if not re.search(rf"\b{re.escape(numbers[label])}\b", shown_text)]
        assert missing == [], f"not shown in {name}'s Markdown cells: {missing}"
    except BaseException:
        SCREENSHOTS.mkdir(parents=True, exist_ok=True)
        page.screenshot(path=str(SCREENSHOTS / f"jupyterlab_roles_{name[:2]}_failure.png"))
        raise
    finally:
        page.close()
