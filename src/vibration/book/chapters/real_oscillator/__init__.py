"""Part III, the real oscillator: does the paper's model hold on a real driven, damped torsional wheel?

Modules: :mod:`.params` (the chapter's parameter schema), :mod:`.study` (the computation on the lab
data, one frozen record), :mod:`.figures`, :mod:`.text` (sentences and tables),
:mod:`.verdicts` (the paper's claims and the twin questions on the hardware) and
:mod:`.panel` (the kernel-free free-decay panel and its JupyterLab widget).
"""

from vibration.book.chapters.real_oscillator.params import SCHEMA, Params
from vibration.book.chapters.real_oscillator.study import RealOscillatorStudy, real_oscillator_study

__all__ = ["SCHEMA", "Params", "RealOscillatorStudy", "real_oscillator_study"]
