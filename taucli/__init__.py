"""taucli: rigid-body rotation about a fixed axis, tau_net = I alpha, at the terminal."""

__version__ = "0.1.0"
