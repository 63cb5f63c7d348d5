"""How a traced function is written out: emission order and lanes, names, the templates."""
