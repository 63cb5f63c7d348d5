"""The traced algorithms: one module per algorithm, each mirroring the runtime pass of the same name
over symbolic scalars. `model.TracedModel` holds the robot constants and the symbolic inputs."""
