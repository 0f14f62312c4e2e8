"""What Make Wet sets in the scene so that EEVEE draws the wet coat as
Cycles does: EEVEE's reflection switch (Raytracing in 4.2+, Screen Space
Reflections before). Off (EEVEE's default), EEVEE reflects only its light
probes: a smooth coat shows the world where Cycles shows the ground and the
other objects, a sky-coloured rim 5-9 % brighter than Cycles (issue 46).
Set inside Make Wet's undo step: Ctrl-Z puts the setting back."""

from . import compat


def ensure_reflections(scene):
    """Turns the switch on when it is off; returns the sentence for the
    operator's report, or None when nothing changed."""
    switch = compat.eevee_reflection_switch(scene)
    if switch is None:
        return None
    owner, prop, _hint = switch
    if getattr(owner, prop):
        return None
    setattr(owner, prop, True)
    label = owner.bl_rna.properties[prop].name
    return f"EEVEE's {label} turned on for the scene (the wet coat reflects the scene, as in Cycles; Ctrl-Z undoes)"


def ensure_exact_lookups(scene, settings):
    """In a scene rendered with EEVEE, Make Wet builds the exact-lookup
    path: EEVEE's own texture smoothing of the core's tables costs up to
    8.8 % of the colour against 0.16 % exact (price.json's
    eevee_colour_error, from the dated benchmark). Cycles gives the same
    colours either way, faster without, so a Cycles scene keeps the
    setting. Returns the sentence for the report, or None."""
    if not compat.is_eevee(scene.render.engine) or settings.exact_lookups or compat.exact_lookups_required():
        return None
    settings.exact_lookups = True
    return "Exact lookups turned on for this material (EEVEE reads the core's colours exactly; Ctrl-Z undoes)"
