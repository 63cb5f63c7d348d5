"""The robot as the algorithms see it while tracing: constants lifted to expressions, inputs as
symbols (or zeros, for the inputs a scene declares zero), and the per-joint quantities of paper 000
Section 3 (X_T, X_J, S_i, I_i) built once per traced function."""

from __future__ import annotations


from . import coupled, regrouped
from ..graph import expr as ex
from ..graph import spatial as sp


class TracedModel:
    """Per-function view of (robot, scene) with symbolic inputs.

    `inputs` maps an input array name (q, v, a, tau, f, ground_mass, restitution) to its length; an input the
    scene declares zero is all constant zeros, so everything depending on it folds away."""

    def __init__(self, robot, scene, zero_inputs=(), known_inputs=None):
        self.robot = coupled.tree_view(robot)  # the algorithms see the tree (views/coupled.py)
        self.coupled = robot                     # the inputs have its independent coordinates
        self.scene = scene
        self.feet = scene.feet_for(robot)
        self.frames = scene.frames_for(robot)
        self.contacts = scene.contacts_for(robot)
        self.gravity = sp.vec(scene.gravity_for(robot))
        self.zero_inputs = tuple(zero_inputs)
        self.known_inputs = known_inputs or {}   # {name: floats}: traced as constants, so all folds
        self._cache = {}

    # --- inputs -------------------------------------------------------------------------------
    def input(self, name, size):
        key = ("input", name)
        if key not in self._cache:
            if name in self.zero_inputs:
                self._cache[key] = sp.zeros(size)
            elif name in self.known_inputs:
                self._cache[key] = tuple(ex.const(x) for x in self.known_inputs[name])
            else:
                self._cache[key] = tuple(ex.symbol(name, k) for k in range(size))
        return self._cache[key]

    def tree_input(self, name, size):
        """Input `name` of `size` independent coordinates, expanded to the tree's (views/coupled.py)."""
        key = ("tree", name)
        if key not in self._cache:
            self._cache[key] = coupled.expand(self.coupled, name, self.input(name, size))
        return self._cache[key]

    @property
    def q(self):
        return self.tree_input("q", self.coupled.nq)

    @property
    def v(self):
        return self.tree_input("v", self.coupled.nv)

    @property
    def tree_velocity(self):
        """v over the traced tree's dofs (the lane model's: the trunk's and the lane limb's)."""
        return self.v

    @property
    def a(self):
        return self.tree_input("a", self.coupled.nv)

    @property
    def tree_acceleration(self):
        """a over the traced tree's dofs (as tree_velocity)."""
        return self.a

    @property
    def tau(self):
        return self.input("tau", self.coupled.n_joints)

    @property
    def f(self):
        return self.input("f", 3 * len(self.feet))

    @property
    def ground_mass(self):
        return self.input("ground_mass", 1)[0]

    @property
    def restitution(self):
        return self.input("restitution", 1)[0]

    def foot_force(self, k):
        return self.f[3 * k:3 * k + 3]

    def mark(self, phase, body=None):
        """Labels the nodes traced from here on with the phase (and body) of the algorithm; the
        emitter prints the label as a marker comment where it changes."""
        name = "" if body is None else ": body %d %s" % (body, self.robot.bodies[body].name)
        ex.set_label(phase + name)

    # --- joints -------------------------------------------------------------------------------
    def joint(self, i):
        return self.robot.joints[i]

    def axis(self, i):
        """The unit joint axis in the joint (= child body) frame, round-off entries snapped."""
        return sp.snap_axis(self.joint(i).axis)

    def motion_subspace(self, i):
        """S_i (paper 000 Eq. 13): (axis; 0) for revolute, (0; axis) for prismatic joints."""
        joint = self.joint(i)
        axis = list(self.axis(i))
        zero = [0.0, 0.0, 0.0]
        return sp.vec(axis + zero if joint.type == "revolute" else zero + axis)

    def qi(self, i):
        return self.q[self.joint(i).q_index]

    def vi(self, i):
        return self.v[self.joint(i).v_index]

    def ai(self, i):
        return self.a[self.joint(i).v_index]

    def X_up(self, i):
        """X_λ(i)^i = X_J(q_i) X_T(i) (Eqs. 9-11) as a chain keeping each factor's sparsity."""
        key = ("X_up", i)
        if key not in self._cache:
            self._cache[key] = sp.Chain(self.X_tree(i), self.X_joint(i))
        return self._cache[key]

    def X_tree(self, i):
        """X_T(i) (Eq. 10): joint i's constant placement in λ(i)."""
        joint = self.joint(i)
        rotation = sp.snap_rotation(joint.rotation)
        identity = all(rotation[r][c] == (1.0 if r == c else 0.0) for r in range(3) for c in range(3))
        E_T = sp.mat(rotation)
        r_T = sp.vec(joint.translation) if any(joint.translation) else None
        return sp.Transform(None if identity else E_T, r_T)

    def angle_offset(self, i):
        """The constant φ the sines of joint i's angle take it with, q_i + φ (views/turns.py; 0 else)."""
        return ex.const(self.joint(i).angle_offset)

    def X_joint(self, i):
        """X_J(q_i) (Eq. 9): a rotation about the axis by q_i, or a translation along it."""
        q = self.qi(i)
        if self.joint(i).type == "revolute":
            q = q + self.angle_offset(i)  # 0 folds away
            return sp.Transform(sp.coordinate_rotation(self.axis(i), ex.cos(q), ex.sin(q)), None)
        return sp.Transform(None, tuple(q * a for a in sp.vec(self.axis(i))))

    # --- actuators (docs/model.md, "Actuators"; runtime/src/rotors.hpp) ----------------------------
    def rotor(self, i):
        """Joint i's rotor as (X_rot, S_rot, I_rot), or None: the constant placement on the carrier
        λ(i) (parent → rotor coordinates), the motion subspace gr·(axis; 0) and the spatial inertia
        at the rotor origin (its mass sits there)."""
        actuator = self.joint(i).actuator
        if actuator is None or actuator.rotor is None:
            return None
        key = ("rotor", i)
        if key not in self._cache:
            rotor = actuator.rotor
            rotation = sp.snap_rotation(rotor.rotation)
            identity = all(rotation[r][c] == (1.0 if r == c else 0.0) for r in range(3) for c in range(3))
            X = sp.Transform(None if identity else sp.mat(rotation),
                             sp.vec(rotor.translation) if any(rotor.translation) else None)
            S = sp.vec([rotor.gear_ratio * a for a in sp.snap_axis(rotor.axis)] + [0.0, 0.0, 0.0])
            inertia = sp.Inertia(ex.const(rotor.mass), sp.zeros(3), sp.symmetric(sp.mat(rotor.inertia)))
            self._cache[key] = (X, S, inertia)
        return self._cache[key]

    def armature(self, i):
        """Joint i's reflected inertia on M's diagonal (0 without)."""
        actuator = self.joint(i).actuator
        return 0.0 if actuator is None else actuator.armature

    def into_parent(self, i, value):
        """Body i's wrench or composite inertia (in λ(i) coordinates) as it joins λ(i)'s: unchanged
        here; summed over the lanes where a lane limb meets the trunk (views/limb_lanes.LaneModel)."""
        return value

    def spare_lanes(self, i):
        """Whether body i's lanes 2 and 3 only repeat lanes 0 and 1 (a limb pair's), so that a pass
        may carry a second quantity there (algorithms/rnea.py): never here."""
        return False

    def into_dof(self, k, i, term):
        """Dof k's term as it updates dof i's entries in the LᵀDL factorisation and solve: unchanged
        here; summed over the lanes where a lane limb meets the trunk (views/limb_lanes.LaneModel)."""
        return term

    def into_spine(self, k, row, col, term):
        """Foot k's term in the entry (row, col) of ∂(Jᵀf)/∂q, or (row = col) in dof row's moment χ:
        unchanged here; a lane foot's summed over its lanes where both dofs are the spine's
        (views/limb_lanes.LaneModel)."""
        return term

    def into_root(self, term):
        """A foot's term in an entry between two root dofs (the trunk block of ∂(Jᵀf)/∂q):
        unchanged here; summed over the lanes of a lane foot (views/limb_lanes.LaneModel)."""
        return term

    def feet_values(self, values):
        """Per-foot values (one per traced foot) as the kept feet's: unchanged here; the lane feet's
        lanes taken apart (views/limb_lanes.LaneModel)."""
        return values

    def frame_values(self, values):
        """Per-frame values (one per traced frame: a vector or a matrix) in the scene's frame order:
        unchanged here; a lane frame's lanes taken apart (views/limb_lanes.LaneModel)."""
        return values

    def frame_rows(self, rows):
        """Rows of 6 per traced frame over the traced tree's dofs as the scene's frames' rows over
        the robot's: unchanged here (views/limb_lanes.LaneModel)."""
        return rows

    def scatter_matrix(self, rows):
        """A joint-space matrix (rows) of the traced tree as the robot's: unchanged here; a lane
        limb's entries scattered to every limb (views/limb_lanes.LaneModel)."""
        return rows

    def body_parameters(self):
        """(m, h, Ī) per body of the tree, regrouped (views/regrouped.py, which keeps them per tree)."""
        return regrouped.body_parameters(self.robot)

    def inertia(self, i):
        key = ("inertia", i)
        if key not in self._cache:
            self._cache[key] = sp.Inertia.of(*self.body_parameters()[i])
        return self._cache[key]

    # --- floating base ------------------------------------------------------------------------
    def base_rotation(self):
        """R: trunk → world (active), from the unit quaternion q[3:7] = (w, x, y, z); identity for
        a fixed base."""
        if not self.robot.floating_base:
            return sp.identity3()
        key = ("R",)
        if key not in self._cache:
            self._cache[key] = sp.quaternion_rotation(*self.q[3:7])
        return self._cache[key]

    def base_position(self):
        return self.q[0:3] if self.robot.floating_base else sp.zeros(3)

    def base_velocity(self):
        """v₀ of Alg. 1: trunk twist in trunk coordinates; zero for a fixed base."""
        return self.v[0:6] if self.robot.floating_base else sp.zeros(6)

    def gravity_in_base(self):
        """R_W^0 g_W: gravity in trunk coordinates (Alg. 3)."""
        return sp.mat_tmatvec(self.base_rotation(), self.gravity)
