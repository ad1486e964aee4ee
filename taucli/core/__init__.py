"""The ground floor: what every layer speaks.

Owns the error family and exit statuses (errors), how a number and a unit are written for a person
(written), the names of the choices options offer (names), and the version. Imports nothing of
taucli outside itself: every other layer may import it.
"""
