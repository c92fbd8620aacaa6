"""The data RasterLab ships: scenes, templates, student samples, textures and fonts.

It is a package only so that ``importlib.resources`` finds it wherever the
program is installed (a checkout, a wheel in a venv, pipx, uv tool); no code
lives here.
"""
