"""Reading a quantity: text -> an SI float for a kind, with its notes.

Owns the kinds of quantity and their bounds (kinds), the screen of a text before any unit is
read (screen), engineering spellings (spellings), the expression grammar (expressions), the plain
form "number times unit" read without pint (unit_text), pint's reading of a unit under taucli's
rules (registry), what a unit means for each kind (meanings: Hz, the radian, a joule for a
torque), the units policy in one call (units), the grammar of a measured value "4.0+/-0.1 kg"
(measurement), each unit's SI factor kept between runs (cache) and the table shipped for a first
run (shipped, units-shipped.json).

May import: taucli.core. pint is imported only when a unit is not in the cache.
"""
