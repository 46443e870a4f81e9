"""For tests that signal a child process as a user would (Ctrl-C, kill)."""
import signal


def default_signals():
    """In the child (Popen's preexec_fn): the caught signals at their default disposition. A
    process keeps a signal its parent ignores (nohup, or a background job of a non-interactive
    shell, which ignores SIGINT; Python then installs no KeyboardInterrupt), so a test run launched
    that way would otherwise wait for a signal that never acts."""
    for name in ("SIGINT", "SIGTERM", "SIGHUP"):
        signal.signal(getattr(signal, name), signal.SIG_DFL)
