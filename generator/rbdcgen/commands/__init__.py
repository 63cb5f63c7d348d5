"""The command line and what each subcommand does; pipeline composes the stages."""
