"""What the plugin's picture-taking scripts share (imported by them under pvbatch and pvpython)."""
from paraview.simple import GetActiveViewOrCreate


def dark_render_view():
    """The active render view with no orientation axes and a fixed dark background."""
    view = GetActiveViewOrCreate("RenderView")
    view.OrientationAxesVisibility = 0
    view.Background = [0.1, 0.1, 0.15]
    try:  # ParaView 5.11 takes the background from the colour palette unless told otherwise
        view.UseColorPaletteForBackground = 0
    except AttributeError:
        pass
    return view
