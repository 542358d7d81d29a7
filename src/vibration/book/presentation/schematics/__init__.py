"""Schematics of the book's models, each with the free-body diagram of its mass(es) beside it.

One function per model, each returning a :class:`~vibration.book.presentation.captions.Captioned`
figure at the column width: the schematic on the left, the free-body diagram on the right (and,
where the model needs it, a third or fourth panel). Everything is drawn with matplotlib
patches and lines: springs as zigzags, dashpots as pistons in cylinders, fixed ground hatched.
One colour language throughout: structure black, forces and torques vermillion
(:data:`FORCE`), coordinates blue (:data:`COORDINATE`); a device that is a case of the book's
visual language (the skyhook, the semi-active damper, the Duffing springs) takes the colour of
its case from :func:`~vibration.book.presentation.style.case_style`.

Free-body diagrams are in Newton's form: the arrows are the forces (torques) that act on the
body, drawn in the directions they act when the coordinates and their rates are positive; the
mass times the acceleration is their sum, not a force, and is not drawn. Each force arrow
carries the label it has in the caption (its ``gid`` is ``"force:" + label``), so a test can
count the arrows against the caption.

Functions: :func:`single_mass` (the paper's model, chapters 1-6), :func:`base_excitation`
(chapter 6's isolation, chapter 7's suspension), :func:`two_mass_absorber` (chapter 8),
:func:`shear_building` (chapter 8), :func:`skyhook` (chapter 7), :func:`duffing_spring`
(chapter 9) and :func:`torsional_oscillator` (chapter 12). The drawing kit they share is
:mod:`~vibration.book.presentation.schematics.kit`; the models are drawn in ``one_mass``, ``absorbers``,
``suspension``, ``duffing`` and ``torsional``.

Examples
--------
>>> cap = single_mass()
>>> cap.name, [ax.get_label() for ax in cap.fig.axes]
('fig-schematic-single-mass', ['schematic', 'free-body diagram'])
>>> from vibration.book.presentation.style import WIDTH_IN
>>> float(cap.fig.get_size_inches()[0]) == WIDTH_IN
True
"""

from .absorbers import shear_building, two_mass_absorber
from .duffing import duffing_spring
from .kit import BODY as BODY  # the rest of the colour language, importable from here as before
from .kit import COORDINATE, FORCE
from .kit import HATCH as HATCH
from .kit import INK as INK
from .one_mass import base_excitation, single_mass
from .suspension import skyhook
from .torsional import torsional_oscillator

__all__ = [
    "COORDINATE",
    "FORCE",
    "base_excitation",
    "duffing_spring",
    "shear_building",
    "single_mass",
    "skyhook",
    "torsional_oscillator",
    "two_mass_absorber",
]
