"""Pages of the manual generated from the program itself."""
