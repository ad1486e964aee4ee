"""The draws and the checks of tests/test_definitions.py, one module per scene (check.py: what they share)."""
