"""Speed benchmarks of coinflight, kept apart from the tests. Run all: ``python -m benchmarks``."""
