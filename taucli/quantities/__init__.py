"""Reading a quantity: text -> an SI float for a kind, with its notes.

Owns the kinds of quantity and their bounds (kinds), the screen of a text before any unit is
read (screen), engineering spellings (spellings), the expression grammar (expressions), pint's
reading of a unit under taucli's rules (registry), the units policy in one call (units), the
grammar of a measured value "4.0+/-0.1 kg" (measurement), each unit's SI factor kept between runs
(cache) and the table shipped for a first run (shipped, units-shipped.json).

May import: taucli.core. pint is imported only when a unit is not in the cache.
"""
