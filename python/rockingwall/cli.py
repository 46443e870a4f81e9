"""The `rockingwall` command: subcommands thin over the API (rockingwall <command> --help)."""
import argparse
import importlib
import os
import sys

from . import __version__, outputs, scratch
from .commands import common as cc
from .errors import RockingWallError

# commands with their own argument parser: name -> (module, one-line help)
DELEGATED = {
    "sweep": ("rockingwall.commands.sweep", "a parametric sweep (walls x records x intensities x K_d) on Dask"),
    "ida": ("rockingwall.commands.ida", "incremental dynamic analysis and fragility from a sweep's results"),
    "couple": ("rockingwall.commands.couple", "the wall FMU coupled to the Diaphragm FMU (co-simulation)"),
    "couple-building": ("rockingwall.commands.couple_building", "walls in a Building FMU, second-order co-simulation, SSP"),
    "paper": ("rockingwall.commands.paper", "reproduce the paper's tables and figures"),
    "animate": ("rockingwall.commands.animate", "an animation of the rocking wall under a record"),
    "demo": ("rockingwall.commands.demo", "the main job: the paper's wall 1 under El Centro 1940 at 50 %"),
}


def build_parser():
    from .commands import assess, building, info, run
    width = max(map(len, DELEGATED)) + 2  # the text two spaces after the longest name
    p = argparse.ArgumentParser(prog="rockingwall", description=__doc__ + "\n\n" + "\n".join(
        f"  {name:<{width}}{text}" for name, (_, text) in DELEGATED.items()),
        formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--version", action="version", version=f"rockingwall {__version__}")
    # cc.Parser: a subcommand's description keeps its lines (its examples one command a line)
    sub = p.add_subparsers(title="commands", parser_class=cc.Parser,
                           metavar="{run,assess,building,info," + ",".join(DELEGATED) + "}")
    run.parser(sub)
    assess.parser(sub)
    building.parser(sub)
    info.parser(sub)
    return p


def parse(argv):
    """The arguments of a built-in command (run, assess, building, info). assess's records may
    follow its lists of numbers, as its examples write them (cc.records_before_lists)."""
    if argv and argv[0] == "assess":
        from .commands import assess
        argv = cc.records_before_lists(argv, assess.NUMBER_LISTS)
    return build_parser().parse_args(argv)


def dispatch(argv):
    if argv and argv[0] in DELEGATED:
        return importlib.import_module(DELEGATED[argv[0]][0]).main(argv[1:]) or 0
    args = parse(argv)
    if not hasattr(args, "command"):
        build_parser().print_help()
        return 2
    return args.command(args)


def main(argv=None):
    """Every command. Errors of the package's own kinds (ValueError, RockingWallError: refused
    input, a run that cannot be made) are one line and exit status 2; a file that cannot be read
    or written (a full disk, no permission) one line naming it and exit status 1. What is left is
    a bug and keeps its traceback."""
    argv = sys.argv[1:] if argv is None else list(argv)
    scratch.reclaim_once()  # the temporary folders killed runs of this program left
    try:
        with outputs.session(), outputs.named_stdout():  # inputs never overwritten; stdout's errors named
            return dispatch(argv)
    except (ValueError, RockingWallError) as exc:
        return cc.fail(str(exc))
    except KeyboardInterrupt:
        return cc.fail("interrupted", 130)
    except BrokenPipeError:  # the reader of standard output went away (| head): not an error of ours
        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
        return 0
    except OSError as exc:
        return cc.fail(outputs.describe_os_error(exc), 1)


if __name__ == "__main__":
    sys.exit(main())
