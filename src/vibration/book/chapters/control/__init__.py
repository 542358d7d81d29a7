"""Chapter 7, control: can feedback on the measured motion beat the paper's fixed damper, and at what cost?

Modules: :mod:`.params` (the chapter's parameter schema), :mod:`.study` (the active, semi-active and
input-shaping runs, frozen records), :mod:`.figures` (captioned figures), :mod:`.tables`,
:mod:`.text` (sentences, the key-results box and the designer's summary), :mod:`.notation` (how
numbers and designs are written), :mod:`.panel` (the kernel-free slider panel) and :mod:`.bench`.
"""

from vibration.book.chapters.control.params import SCHEMA, Params
from vibration.book.chapters.control.study import (
    ActiveStudy,
    ControlStudy,
    SemiActiveStudy,
    ShapingStudy,
    active_study,
    control_study,
    semi_active_study,
    shaping_study,
)

__all__ = [
    "SCHEMA",
    "ActiveStudy",
    "ControlStudy",
    "Params",
    "SemiActiveStudy",
    "ShapingStudy",
    "active_study",
    "control_study",
    "semi_active_study",
    "shaping_study",
]
