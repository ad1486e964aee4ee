"""Answering a run: from the texts given to a Report, and how a run is answered.

Owns the loop over a command's table that reads every option (inputs; one quantity: reading;
"key=value" specs and vectors: specs; a CSV torque profile: profile), the scene's library
function called with SI floats (pipeline), and above it the ways of answering: plain, with
uncertainty (propagate), solving for an input (find, unknowns), a sweep (sweep), chosen in
answer.

May import: taucli.core, numerics, quantities, writing, options, scenes.
"""
