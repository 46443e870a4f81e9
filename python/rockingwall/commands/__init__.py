"""The subcommands of `rockingwall`, one module each: their arguments and `main`, over the API."""
