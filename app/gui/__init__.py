"""The window: Qt widgets and actions over the Qt-free model (app/model)."""
from app.gui import pyside_hook

pyside_hook.quicken()  # before pyqtgraph and the window's modules are imported
