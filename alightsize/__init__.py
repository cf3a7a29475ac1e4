"""alightsize: landing-leg design toolkit after AFFDL-TR-66-33 (1966)."""

__version__ = "0.1.0"
