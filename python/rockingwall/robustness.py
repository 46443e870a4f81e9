"""A run's robustness for the API and the commands: its ensemble (rockingwall.ensemble) run on
the scene the run used, and summarised against the limit states beside the nominal outcome."""
from . import ensemble as ens
from . import limits


def as_ensemble(value):
    """An ensemble.Ensemble from one, or from its size (an int)."""
    if isinstance(value, ens.Ensemble):
        return value
    if isinstance(value, bool) or not isinstance(value, int):
        raise ValueError(f"ensemble: an ensemble.Ensemble or its size (an int), not {value!r}")
    return ens.Ensemble(size=value)


def nominal_outcome(states, peaks):
    """{state name: reached, 'collapsed': collapsed} of one run's peaks (a dict with peak_s1,
    peak_s2, peak_F_top, collapsed)."""
    out = {s.name: s.exceeded(peaks) for s in states}
    out["collapsed"] = bool(peaks["collapsed"])
    return out


def members(wall_params, record, t_end, ensemble, diaphragm=None, tie=None, states=()):
    """The ensemble's runs of a wall on its own (diaphragm None) or under a diaphragm with mass
    (the members' tie forces too where one of the limit states `states` is on F_top)."""
    if diaphragm is None:
        return ens.wall_members(wall_params, record, ensemble, t_end)
    return ens.diaphragm_members(wall_params, diaphragm, tie, record, ensemble, t_end, limits.ask_tie_force(states))


def of_result(result, record, t_end, ensemble, diaphragm=None, tie=None, states=None):
    """The ensemble.Summary of an api.Result's case (the default limit states unless given)."""
    states = states if states is not None else limits.parse_all(None, result.wall)
    runs = members(result.wall.params, record, t_end, as_ensemble(ensemble), diaphragm, tie, states)
    peaks = dict(peak_s1=result.peak_s1, peak_s2=result.peak_s2, peak_F_top=result.peak_F_top,
                 collapsed=result.collapsed)
    return ens.summarize(runs, states, nominal_outcome(states, peaks))
