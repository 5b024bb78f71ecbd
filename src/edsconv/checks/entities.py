"""Checks of parameters, assemblies, connections, ports and modules (C.4.1.4.6 - C.4.1.5)."""
