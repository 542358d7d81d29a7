"""Chapter 2, the paper's claims audited against its own method and the exact solution.

Modules: :mod:`.params` (the chapter's parameter schema), :mod:`.study` (the audit, one frozen
record of typed claims), :mod:`.notation` (the audit's words in the reader's notation) and
:mod:`.text` (sentences, the key-results box and tables).
"""

from vibration.book.chapters.claims_audit.params import SCHEMA, Params
from vibration.book.chapters.claims_audit.study import Claim, ClaimsAuditStudy, Reading, claims_audit_study

__all__ = ["SCHEMA", "Claim", "ClaimsAuditStudy", "Params", "Reading", "claims_audit_study"]
