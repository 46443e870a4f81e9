"""`rockingwall animate`'s figure: its title is read whole and names the scene."""
import rockingwall as rw
from rockingwall import animation, records


def test_the_animations_title_fits_and_names_its_scene():
    """The GIF (259 pixels wide) titled 'b = 0.15 m, h = 2.5 m, K_d = 50 kN/m per m, El Centro 1940
    at 0.2 g' on one line, cut at both edges ('...at 0.2 (' was the last thing shown), and did not
    say which scene ran. The title is wrapped to the figure and names the paper's scene."""
    wall = rw.Wall.make(preset="paper1", Kd=5e4)
    rec = records.el_centro().to_pga(0.2)
    fig, _ = animation.figure(wall, rec, 3.0, 5.0)
    fig.canvas.draw()
    title = fig._suptitle
    box = title.get_window_extent()
    assert 0 <= box.x0 and box.x1 <= fig.bbox.width
    text = " ".join(title.get_text().split())
    assert text.startswith("El Centro 1940 at 0.2 g: b = 0.15 m, h = 2.5 m, K_d = 50 kN/m per m")
    assert "scene: the paper's: the top spring K_d = 50 kN/m per m ends at a fixed point" in text
