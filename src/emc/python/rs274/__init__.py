"""rs274: helpers for programs that run G-code through the `gcode` module (previews, tests)."""
from .interpret import Translated, ArcsToSegmentsMixin  # noqa: F401
