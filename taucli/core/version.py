"""taucli's version, in a module of its own: every writer of a document and the cache stamp read it."""

__version__ = "0.1.0"
