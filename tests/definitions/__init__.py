"""The draws and the checks of tests/scenes/test_definitions.py, one module per scene (check.py: what they share)."""
