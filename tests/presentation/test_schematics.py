"""The schematics of the book's models: captions true to the drawing, one arrow per force, legible and tidy.

Each figure is built once per module. The checks measure the drawn figure (window extents after a draw),
not the code that drew it: panel count, force arrows in the free-body diagram against the caption, the
direction of every restoring force, text sizes, overlaps of texts with texts and with drawn lines, and
artists inside their panels.
"""

from __future__ import annotations

import itertools
import re

import matplotlib.pyplot as plt
import numpy as np
import pytest
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.patches import FancyArrowPatch
from matplotlib.text import Text

from vibration.book.presentation import schematics, style
from vibration.book.presentation.captions import CAPTION_WORDS, Captioned, caption_words, check_caption, panel_words

# every test here builds on a study, a figure set or a browser that takes seconds: make test-slow runs them
pytestmark = pytest.mark.slow

#: name: (panels, force arrows in the free-body diagram)
EXPECTED = {
    "single_mass": (2, 5),  # kx, c x', F0 sin wt, mg, N
    "base_excitation": (2, 2),  # k(x - y), c(x' - y')
    "two_mass_absorber": (2, 7),  # k_a and c_a on each mass, k_p x_p, c_p x_p', F0 sin wt
    "shear_building": (2, 2),  # the storey shears above and below
    "skyhook": (4, 3),  # k(x - y), c(x' - y'), f
    "duffing_spring": (3, 5),  # kx + k3 x^3, c x', F0 cos wt, mg, N
    "torsional_oscillator": (2, 4),  # drive, kappa theta, b theta', tau_c sgn theta'
}

#: Direction each force acts in, for positive coordinates and rates: (dx, dy) signs for straight arrows,
#: +1 (counter-clockwise) or -1 (clockwise) for torques. Restoring forces oppose the coordinate.
DIRECTIONS = {
    "single_mass": {
        "$kx$": (-1, 0),
        r"$c\dot x$": (-1, 0),
        r"$F_0\sin\omega t$": (1, 0),
        "$mg$": (0, -1),
        "$N$": (0, 1),
    },  # fmt: skip
    "base_excitation": {"$k(x - y)$": (0, -1), r"$c(\dot x - \dot y)$": (0, -1)},
    "shear_building": {"$k(x_{j+1} - x_j)$": (1, 0), "$k(x_j - x_{j-1})$": (-1, 0)},
    "skyhook": {"$k(x - y)$": (0, -1), r"$c(\dot x - \dot y)$": (0, -1), "$f$": (0, 1)},
    "duffing_spring": {"$kx + k_3x^3$": (-1, 0), r"$c\dot x$": (-1, 0), r"$F_0\cos\omega t$": (1, 0)},
    "torsional_oscillator": {
        r"$\tau_0\sin\omega t$": 1,
        r"$\kappa\theta$": -1,
        r"$c_\theta\dot\theta$": -1,
        r"$\tau_c\,\mathrm{sgn}\,\dot\theta$": -1,
    },  # fmt: skip
}


@pytest.fixture(scope="module")
def figures():
    made = {name: getattr(schematics, name)() for name in EXPECTED}
    for cap in made.values():
        FigureCanvasAgg(cap.fig)  # Captioned closed the pyplot figure; measure on an Agg canvas
        cap.fig.canvas.draw()
    yield made
    for cap in made.values():
        plt.close(cap.fig)


def _fbd(fig):
    (ax,) = [ax for ax in fig.axes if ax.get_label() == "free-body diagram"]
    return ax


def _texts(fig) -> list[Text]:
    return [t for t in fig.findobj(Text) if t.get_visible() and t.get_text().strip()]


def _arrow_points(arrow: FancyArrowPatch) -> np.ndarray:
    """The arrow's outline in display coordinates (shaft and head)."""
    path = arrow.get_path()
    return arrow.get_transform().transform(path.interpolated(8).vertices)


def _tail_tip(arrow: FancyArrowPatch) -> tuple[np.ndarray, np.ndarray]:
    """Tail (first point of the shaft) and tip (the outline's point farthest from the tail), display coordinates."""
    pts = _arrow_points(arrow)
    tail = pts[0]
    tip = pts[np.argmax(np.hypot(*(pts - tail).T))]
    return tail, tip


@pytest.mark.parametrize("name", EXPECTED)
def test_a_captioned_figure_whose_caption_is_true_to_it(figures, name):
    cap = figures[name]
    assert isinstance(cap, Captioned)
    assert cap.name.startswith("fig-schematic-")
    check_caption(cap.fig, cap.caption)  # raises if the caption contradicts the drawing
    assert cap.alt.strip().endswith(".") and len(cap.alt.split()) >= 12, "a sentence, not a label"
    words = panel_words(cap.fig)
    assert len(words) == EXPECTED[name][0], words
    for word in words:
        assert word.lower() in cap.caption.lower(), f"the caption leaves out the {word} panel"
    told = cap.caption + " " + cap.remark
    assert told.count("Newton's form") == 1, "the caption or its remark states the free-body diagram's convention once"


def test_the_names_are_distinct(figures):
    names = [cap.name for cap in figures.values()]
    assert len(set(names)) == len(names)


@pytest.mark.parametrize("name", EXPECTED)
def test_one_arrow_per_force_named_in_the_caption(figures, name):
    cap = figures[name]
    ax = _fbd(cap.fig)
    arrows = [p for p in ax.patches if isinstance(p, FancyArrowPatch)]
    forces = [a.get_gid()[len("force:") :] for a in arrows if (a.get_gid() or "").startswith("force:")]
    assert len(forces) == EXPECTED[name][1], forces
    assert all((a.get_gid() or "").startswith(("force:", "coordinate:")) for a in arrows), "every arrow is named"
    assert not [t for t in ax.texts if getattr(t, "arrow_patch", None)], "no annotate arrows outside the count"
    labels = {t.get_text() for t in ax.texts}
    for label in set(forces):
        assert label in cap.caption, f"{label} is drawn but not named in the caption"
        assert label in labels, f"the arrow {label} has no label in the diagram"
    # the caption names no force of the diagram that is not drawn: every maths term that labels a force
    # anywhere in the figure is one of the diagram's arrows
    load_labels = {
        p.get_gid()[len("load:") :] for a in cap.fig.axes for p in a.patches if (p.get_gid() or "").startswith("load:")
    }
    assert load_labels <= set(forces), "a load on the schematic is missing from the free-body diagram"


@pytest.mark.parametrize("name", DIRECTIONS)
def test_forces_point_the_way_they_act(figures, name):
    ax = _fbd(figures[name].fig)
    arrows = {a.get_gid()[len("force:") :]: a for a in ax.patches if (a.get_gid() or "").startswith("force:")}
    for label, want in DIRECTIONS[name].items():
        tail, tip = _tail_tip(arrows[label])
        d = tip - tail
        if isinstance(want, tuple):
            assert np.sign(np.round(d / np.hypot(*d), 6)).tolist() == list(want), (label, d)
        else:  # a torque about the wheel's centre: the sign of the turn from tail to tip
            centre = ax.transData.transform((0.0, 0.0))
            (ax_, ay_), (bx, by) = tail - centre, tip - centre
            turn = ax_ * by - ay_ * bx
            assert np.sign(turn) == want, (label, turn)


@pytest.mark.parametrize("name", EXPECTED)
def test_text_at_least_8_pt_and_the_column_width(figures, name):
    fig = figures[name].fig
    assert fig.get_size_inches()[0] == pytest.approx(style.WIDTH_IN, abs=1e-12)
    small = [(t.get_text(), t.get_fontsize()) for t in _texts(fig) if t.get_fontsize() < 8.0]
    assert not small, small


@pytest.mark.parametrize("name", EXPECTED)
def test_every_drawn_symbol_is_explained_in_the_caption_or_its_remark(figures, name):
    cap = figures[name]
    symbols = {m for t in _texts(cap.fig) for m in re.findall(r"\$[^$]+\$", t.get_text())}
    assert symbols, "the figure labels its symbols"
    missing = sorted(s for s in symbols if s not in cap.caption + " " + cap.remark)
    assert not missing, f"drawn but not in the caption or its remark: {missing}"


def _far_schematics(figures):
    """Every schematic under its defaults and under far arguments: the fewest and the most storeys, and a rig
    whose data document everything the torsional caption can quote."""
    yield from figures.values()
    yield from (schematics.shear_building(n) for n in (2, 3, 8))
    long = "a brass wheel of 0.2 m diameter on a spiral spring, rocked by a 24 V motor through an eccentric and a rod"
    yield schematics.torsional_oscillator(description=long, max_angle_rad=3.14159, encoder_step_rad=0.00153398)


def test_every_caption_is_at_most_60_words_under_defaults_and_far_arguments(figures):
    """What is drawn fits the book's caption limit; the free-body detail lives in the remark."""
    long = {}
    for cap in _far_schematics(figures):
        plt.close(cap.fig)
        assert cap.remark.strip(), f"{cap.name}: the free-body detail has a remark to go to"
        if caption_words(cap.caption) > CAPTION_WORDS:
            long[cap.name] = caption_words(cap.caption)
    assert CAPTION_WORDS == 60
    assert not long, long


def test_no_sentence_closes_several_schematics(figures):
    """A shared closing sentence (the convention of the free-body diagrams, the colour of the forces) is said in each
    figure's own words: no sentence, formulas and numbers masked, appears in more than two schematics."""
    seen: dict[str, set[str]] = {}
    for name in EXPECTED:
        cap = figures[name]
        text = re.sub(r"\$[^$]*\$", "§", cap.caption + " " + cap.remark)
        text = re.sub(r"\d+(\.\d+)?", "#", text)
        for sentence in re.split(r"(?<=[.;])\s+", text):
            words = sentence.split()
            if len(words) >= 5:
                seen.setdefault(" ".join(words).lower(), set()).add(name)
    repeated = {s: sorted(names) for s, names in seen.items() if len(names) > 2}
    assert not repeated, repeated
    for name in EXPECTED:
        cap = figures[name]
        sentences = [s for s in re.split(r"(?<=\.)\s+", cap.caption) if len(s.split()) >= 3]
        assert len(sentences) == len(set(sentences)), f"{name}: a sentence repeats within the caption"


@pytest.mark.parametrize("name", EXPECTED)
def test_no_text_overlaps_another(figures, name):
    fig = figures[name].fig
    renderer = fig.canvas.get_renderer()
    boxes = [(t.get_text(), t.get_window_extent(renderer)) for t in _texts(fig)]
    clashes = []
    for (ta, a), (tb, b) in itertools.combinations(boxes, 2):
        w = min(a.x1, b.x1) - max(a.x0, b.x0)
        h = min(a.y1, b.y1) - max(a.y0, b.y0)
        if w > 1.0 and h > 1.0:
            clashes.append((ta, tb, round(w, 1), round(h, 1)))
    assert not clashes, clashes


@pytest.mark.parametrize("name", EXPECTED)
def test_no_text_sits_on_a_line_or_an_arrow(figures, name):
    """Labels beside their springs, dashpots, bodies and arrows, not on them (legend entries and axis labels
    aside); a label inside a body (m on the block) touches no outline."""
    fig = figures[name].fig
    renderer = fig.canvas.get_renderer()
    hits = []
    for ax in fig.axes:
        shapes = []
        for line in ax.get_lines():
            xy = line.get_xydata()
            if len(xy) < 2:
                continue
            s = np.linspace(0, len(xy) - 1, 40 * len(xy))
            dense = np.column_stack([np.interp(s, np.arange(len(xy)), xy[:, i]) for i in (0, 1)])
            shapes.append((f"line {line.get_color()}", line.get_transform().transform(dense)))
        for p in ax.patches:
            if isinstance(p, FancyArrowPatch):
                shapes.append((p.get_gid(), _arrow_points(p)))
            else:  # outlines of bodies, wheels, hatched ground
                shapes.append((type(p).__name__, p.get_transform().transform(p.get_path().interpolated(40).vertices)))
        for t in ax.texts:
            if not t.get_text().strip():
                continue
            box = t.get_window_extent(renderer).expanded(1.0, 1.0)
            x0, y0, x1, y1 = box.x0 + 1, box.y0 + 1, box.x1 - 1, box.y1 - 1
            for what, pts in shapes:
                inside = (pts[:, 0] > x0) & (pts[:, 0] < x1) & (pts[:, 1] > y0) & (pts[:, 1] < y1)
                if inside.any():
                    hits.append((ax.get_label(), t.get_text(), what))
    assert not hits, hits


@pytest.mark.parametrize("name", EXPECTED)
def test_nothing_drawn_outside_the_figure_or_its_panel(figures, name):
    fig = figures[name].fig
    renderer = fig.canvas.get_renderer()
    page = fig.bbox
    outside = []
    for ax in fig.axes:
        panel = ax.get_window_extent(renderer) if ax.get_label() != "restoring force" else None
        artists = list(ax.patches) + list(ax.lines) + list(ax.collections) + list(ax.texts)
        for art in artists:
            box = art.get_window_extent(renderer)
            if box.x0 < page.x0 - 1 or box.y0 < page.y0 - 1 or box.x1 > page.x1 + 1 or box.y1 > page.y1 + 1:
                outside.append(("figure", ax.get_label(), art))
            if panel is not None and (
                box.x0 < panel.x0 - 1 or box.y0 < panel.y0 - 1 or box.x1 > panel.x1 + 1 or box.y1 > panel.y1 + 1
            ):
                outside.append(("panel", ax.get_label(), art))
    for t in _texts(fig):
        box = t.get_window_extent(renderer)
        if box.x0 < page.x0 - 1 or box.y0 < page.y0 - 1 or box.x1 > page.x1 + 1 or box.y1 > page.y1 + 1:
            outside.append(("figure", "text", t.get_text()))
    assert not outside, outside


@pytest.mark.parametrize("n", [2, 3, 8])
def test_the_building_has_n_storeys(n):
    cap = schematics.shear_building(n)
    left = next(ax for ax in cap.fig.axes if ax.get_label() == "schematic")
    floors = [t for t in left.texts if t.get_text() == "$m$"]
    coords = {t.get_text() for t in left.texts if re.fullmatch(r"\$x_\d\$", t.get_text())}
    assert len(floors) == n
    assert coords == {f"$x_{j}$" for j in range(1, n + 1)}
    assert f"{n}-storey" in cap.caption
    assert caption_words(cap.caption) <= CAPTION_WORDS
    assert f"$x_1$ to $x_{n}$" in cap.caption if n > 2 else "$x_1$, $x_2$ and $x_a$" in cap.caption
    assert ", ".join(f"$x_{j}$" for j in range(1, n + 1)) + " (m)" in cap.remark, "the remark names every floor"
    plt.close(cap.fig)


@pytest.mark.parametrize("n", [1, 9, 2.5, True, "5"])
def test_the_building_refuses_a_bad_storey_count(n, raises_parameter_error):
    with raises_parameter_error("n", n, "2", "8"):
        schematics.shear_building(n)


def test_the_legend_leaves_the_curves_free(figures):
    ax = next(a for a in figures["duffing_spring"].fig.axes if a.get_label() == "restoring force")
    assert ax.get_legend() is not None
    assert style.legend_overlap(ax) == 0.0
