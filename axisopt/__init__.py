"""axisopt: size machine-tool feed axes from real catalogs and diagnose measured axes."""

__version__ = "0.1.0"
