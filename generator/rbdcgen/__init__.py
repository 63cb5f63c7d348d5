"""rbdcgen: the rigid-body dynamics compiler (IR → traced scalar DAG → Jinja2-rendered C++)."""
