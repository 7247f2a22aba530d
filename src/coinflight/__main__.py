"""``python -m coinflight``: the same as the ``coinflight`` command."""

from coinflight.cli import main

if __name__ == "__main__":
    main()
