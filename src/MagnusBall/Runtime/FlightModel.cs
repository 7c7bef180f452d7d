using System;
using System.Runtime.CompilerServices;
using MagnusBall.Aerodynamics;

namespace MagnusBall
{
    /// <summary>
    /// The right-hand side of the flight ODE: given a <see cref="FlightState"/>, the rates of change of
    /// position, velocity and spin under gravity, drag, Magnus lift and spin decay. Immutable and
    /// thread-safe: one model can be shared by any number of balls and threads.
    /// </summary>
    /// <remarks>
    /// <para>With air-relative velocity v_rel = v - wind (the wind at the ball, <see cref="Air.WindAt"/>), speed s = |v_rel|, v_hat = v_rel / s,
    /// cross-section A = pi r^2 and mass m, the acceleration is</para>
    /// <code>
    /// a = g - (rho A / 2m) C_D s v_rel + (rho A / 2m) C_L s^2 (w x v_hat) / |w|
    /// </code>
    /// <para>Gravity and drag are the seed thesis's (Agrawal 2023, eqs. 4-5 and 9-11). The Magnus term is
    /// the transverse-spin form: the thesis writes 1/2 C_M rho A s^2 (w x v)/|w x v| (its eq. 2, after
    /// Javorova &amp; Ivanov 2018), which is the same whenever w is perpendicular to v (top-, back- and
    /// sidespin) but undefined when w is parallel to v. Here only the spin component across the flight
    /// lifts, |w x v_hat| = |w_perp|, so pure "gyro" spin gives no force and nothing is ever divided by zero.
    /// See docs/physics.md.</para>
    /// <para>Each term can be left out, so a scene models only what it needs and pays only for that:
    /// a null drag, lift or spin-decay model switches the term off, and zero gravity is allowed.</para>
    /// </remarks>
    public sealed class FlightModel
    {
        /// <summary>
        /// Below this air-relative speed (m/s) the aerodynamic forces are taken as exactly zero. They scale
        /// with s^2 (or s|w| for lift linear in spin) and are far below double precision's resolution of
        /// gravity there; the cut-off keeps 1/s from overflowing.
        /// </summary>
        internal const double MinimumAerodynamicSpeed = 1e-150;

        /// <summary>
        /// At or below this spin rate (rad/s) the lift is taken as exactly zero. A lift law whose C_L vanishes like the
        /// spin parameter (Stepanek's, Nathan's, a linear one) gives far less than double precision's resolution of
        /// gravity there; a C_L that does not vanish at S = 0 (a constant, as in the thesis model, or a table whose first
        /// C_L is not 0) would give its full Magnus force for any spin however small, and its direction, (w x v_hat) / |w|,
        /// from a quotient by |w| that overflows near 1e-308 rad/s (1/|w| below 1/double.MaxValue = 5.6e-309 rad/s): such
        /// a law's lift jumps to 0 here. The same cut-off everywhere: the general formula, the kernel, the ball batch.
        /// </summary>
        internal const double MinimumLiftSpinRate = 1e-150;

        private readonly double _dragFactor; // rho A / (2 m), 1/m
        private readonly double _kinematicRadius;
        private readonly double _viscosity;
        private readonly bool _hasAero;
        private readonly bool _windVaries; // a wind profile: the wind depends on the height
        private readonly Vector3d _wind;   // the uniform wind (read once here, not per evaluation)
        private readonly double _gravityLength;
        private readonly double _coefficientBound; // >= |C_D| + |C_L| for every input, or -1 when a law has no known bound
        private readonly double _decayRateBound;   // >= |dw/dt| / |w| for every input (with _coefficientBound >= 0)
        private EvaluationCount? _counted; // the test hook (CountedEvaluations)

        /// <summary>Creates a flight model.</summary>
        /// <param name="ball">The ball (mass, radius, inertia).</param>
        /// <param name="air">The air (density, wind).</param>
        /// <param name="gravity">The gravity vector, m/s^2 (finite; any direction; zero for no gravity).</param>
        /// <param name="drag">The drag-coefficient law, or null for no drag.</param>
        /// <param name="lift">The lift (Magnus) coefficient law, or null for no Magnus force.</param>
        /// <param name="spinDecay">The spin-decay law, or null for constant spin.</param>
        /// <exception cref="ArgumentNullException">ball or air is null.</exception>
        /// <exception cref="ArgumentException">gravity has a non-finite component.</exception>
        public FlightModel(
            Ball ball,
            Air air,
            Vector3d gravity,
            IDragModel? drag = null,
            ILiftModel? lift = null,
            ISpinDecayModel? spinDecay = null)
        {
            Ball = Require.NotNull(ball, nameof(ball));
            Air = Require.NotNull(air, nameof(air));
            Gravity = Require.Finite(gravity, nameof(gravity));
            Drag = drag;
            Lift = lift;
            SpinDecay = spinDecay;
            Up = (-gravity).NormalizedOrZero();
            _dragFactor = air.Density * ball.CrossSectionalArea / (2 * ball.Mass);
            if (!double.IsFinite(_dragFactor))
            {
                // pi r^2 or 2 m overflowed (a ball of radius 1e200 m or mass 1e308 kg): group as (rho / m) (pi r / 2) r,
                // finite whenever k is, never NaN.
                _dragFactor = Overflow.Multiply(Overflow.Multiply(air.Density / ball.Mass, 0.5 * Math.PI * ball.Radius), ball.Radius);
            }
            _kinematicRadius = ball.Radius;
            _viscosity = air.DynamicViscosity;
            _hasAero = (drag != null || lift != null) && air.Density > 0;
            _windVaries = air.WindProfile != null && Up.LengthSquared > 0;
            _wind = air.Wind;
            _gravityLength = gravity.Length;
            // The laws' bounds from the one list of built-in laws (LawCatalogue): a law it does not bound has none.
            _coefficientBound = !_hasAero ? 0 : LawCatalogue.TraitsOf(drag).Bound is double d && LawCatalogue.TraitsOf(lift).Bound is double l ? d + l : -1;
            _decayRateBound = LawCatalogue.TraitsOf(spinDecay).Bound ?? double.PositiveInfinity;
        }

        /// <summary>The ball.</summary>
        public Ball Ball { get; }

        /// <summary>The air.</summary>
        public Air Air { get; }

        /// <summary>The gravity vector, m/s^2.</summary>
        public Vector3d Gravity { get; }

        /// <summary>The unit vector opposite to gravity (zero when gravity is zero).</summary>
        public Vector3d Up { get; }

        /// <summary>The drag-coefficient law, or null when drag is off.</summary>
        public IDragModel? Drag { get; }

        /// <summary>The lift-coefficient law, or null when the Magnus force is off.</summary>
        public ILiftModel? Lift { get; }

        /// <summary>The spin-decay law, or null when spin is constant.</summary>
        public ISpinDecayModel? SpinDecay { get; }

        /// <summary>
        /// The aerodynamic factor k = rho A / (2 m), 1/m: drag deceleration is k C_D s^2. With x = h k C_D s
        /// (the step in units of the drag time scale), explicit Euler's speed starts to oscillate at x = 1, and the
        /// flight diverges at x = 2 (Euler, Heun), 2.45 (RK4), 1.41 (Dormand-Prince), measured in docs/integrators.md;
        /// StableIntegrator substeps to stay well inside.
        /// </summary>
        internal double AerodynamicFactor => _dragFactor;

        /// <summary>
        /// Test hook: when set, every evaluation of the model (a call of <see cref="Derivative"/> or one inside a kernel step) adds one to it, so tests count real evaluations of
        /// the model instead of trusting a counter's formula. Null (no cost but one check) in every shipped use.
        /// </summary>
        internal EvaluationCount? CountedEvaluations
        {
            get => _counted;
            set
            {
                _counted = value;
                Specialised = null; // the kernel takes the hook when it is next built (Integration/Kernels/FlightKernel.Of)
            }
        }

        /// <summary>
        /// The integration layer's kernel for this model (Integration/Kernels: FlightKernel.Of builds it on first use and
        /// keeps it here). Typed as object: the physics layer holds it without knowing the integration layer.
        /// </summary>
        internal object? Specialised;

        /// <summary>True when the air exerts a force (density &gt; 0 and a drag or lift law): the one place this is decided.</summary>
        internal bool HasAerodynamics => _hasAero;

        /// <summary>A vacuum model: gravity only.</summary>
        /// <param name="ball">The ball.</param>
        /// <param name="gravity">The gravity vector, m/s^2.</param>
        public static FlightModel Vacuum(Ball ball, Vector3d gravity) => new FlightModel(ball, MagnusBall.Air.Vacuum, gravity);

        /// <summary>
        /// The seed thesis's model: constant C_D = 0.55 and C_M = 0.175 (Agrawal 2023), no spin decay.
        /// </summary>
        /// <param name="ball">The ball.</param>
        /// <param name="air">The air.</param>
        /// <param name="gravity">The gravity vector, m/s^2.</param>
        public static FlightModel Thesis(Ball ball, Air air, Vector3d gravity) =>
            new FlightModel(ball, air, gravity, ConstantDrag.ThesisTennis, ConstantLift.ThesisTennis);

        /// <summary>A copy with another drag law (null switches drag off).</summary>
        /// <param name="drag">The drag law.</param>
        public FlightModel WithDrag(IDragModel? drag) => new FlightModel(Ball, Air, Gravity, drag, Lift, SpinDecay);

        /// <summary>A copy with another lift law (null switches the Magnus force off).</summary>
        /// <param name="lift">The lift law.</param>
        public FlightModel WithLift(ILiftModel? lift) => new FlightModel(Ball, Air, Gravity, Drag, lift, SpinDecay);

        /// <summary>A copy with another spin-decay law (null keeps spin constant).</summary>
        /// <param name="spinDecay">The spin-decay law.</param>
        public FlightModel WithSpinDecay(ISpinDecayModel? spinDecay) => new FlightModel(Ball, Air, Gravity, Drag, Lift, spinDecay);

        /// <summary>A copy with other air.</summary>
        /// <param name="air">The air.</param>
        public FlightModel WithAir(Air air) => new FlightModel(Ball, air, Gravity, Drag, Lift, SpinDecay);

        /// <summary>A copy with another gravity vector.</summary>
        /// <param name="gravity">The gravity vector, m/s^2.</param>
        public FlightModel WithGravity(Vector3d gravity) => new FlightModel(Ball, Air, gravity, Drag, Lift, SpinDecay);

        /// <summary>
        /// The right-hand side of the ODE at <paramref name="state"/>: one derivative evaluation, the unit
        /// of cost every integrator is measured in. Allocates nothing; finite for every finite state whose forces fit
        /// in a double, never NaN (with coefficient laws that never return NaN, as every shipped law does).
        /// </summary>
        /// <remarks>
        /// Never NaN for a finite state. Speeds and spins of any finite size are handled: lengths are scaled
        /// before squaring and every product with a zero factor is zero, so each component is finite whenever its
        /// true value fits in a double (a 1 kg ball at v = (1e150, 0, 0) gets its true drag, not NaN). A component whose true
        /// value exceeds double.MaxValue (a tennis ball at 1e155 m/s: k C_D s^2 = 2e308) is +-infinity: the state
        /// then diverges in the integrator, which the steppers report. (Saturating at double.MaxValue instead was
        /// measured to hide such divergence: RK4's stages cancel to a finite, meaningless state.) Everyday states take
        /// the plain formulas (bit for bit as before); only a non-finite result falls back to the scaled path.
        /// </remarks>
        /// <param name="state">The state (not validated here: the integrators validate what they are given).</param>
        /// <remarks>
        /// This is the spec: the textbook formula term by term, every law called through its public interface (see
        /// docs/architecture.md, "The spec"). The library's integrators and flights evaluate the same right-hand side
        /// through a kernel specialised for the model's laws (each built-in law a struct the JIT inlines, only the inputs
        /// some law reads computed), which gives these bits except in its two folded forms, equal to them to rounding
        /// (within a few ulp of the largest term): a lift law that reads no spin parameter (a constant C_L, as in
        /// <see cref="Thesis"/>), and <see cref="StepanekLift"/> beside <see cref="StepanekDrag"/> in still air or a
        /// uniform wind (the tennis presets). A conformance test holds every fast form to this method.
        /// </remarks>
        public StateDerivative Derivative(in FlightState state)
        {
            _counted?.Add();
            return GeneralDerivative(state); // which takes the scaled formula where the plain one overflows (speeds past ~1e150 m/s)
        }

        /// <summary>
        /// The general formula, every law called through its interface: what <see cref="Derivative"/> computes, bit for
        /// bit, except in the kernel's folded forms (to rounding; the tests hold the kernel to both).
        /// </summary>
        /// <param name="state">The state.</param>
        internal StateDerivative GeneralDerivative(in FlightState state)
        {
            Vector3d acceleration = Gravity;
            Vector3d spinAcceleration = default;
            Vector3d w = state.AngularVelocity;

            if (_hasAero || SpinDecay != null)
            {
                // Wind at the ball: uniform (a field read), or from the profile at the ball's height.
                Vector3d relative = state.Velocity - (_windVaries ? Air.WindAt(state.Position, Up) : _wind);
                double speed = relative.Length;
                double spinRate = w.Length;
                AeroConditions conditions;
                if (speed > MinimumAerodynamicSpeed)
                {
                    Vector3d direction = relative / speed;
                    Vector3d spinCrossDirection = Vector3d.Cross(w, direction);
                    conditions = new AeroConditions(
                        speed, spinRate, spinCrossDirection.Length, _kinematicRadius, Air.Density, _viscosity);

                    if (_hasAero)
                    {
                        if (Drag != null)
                        {
                            // F_D / m = -(rho A / 2m) C_D s v_rel  (thesis eq. 4-5)
                            double dragScale = -_dragFactor * Drag.DragCoefficient(conditions) * speed;
                            acceleration += relative * dragScale;
                        }

                        if (Lift != null && spinRate > MinimumLiftSpinRate)
                        {
                            // F_M / m = (rho A / 2m) C_L s^2 (w x v_hat) / |w|  (transverse-spin form)
                            double liftScale = _dragFactor * Lift.LiftCoefficient(conditions) * speed * speed / spinRate;
                            acceleration += spinCrossDirection * liftScale;
                        }
                    }
                }
                else
                {
                    conditions = new AeroConditions(0, spinRate, 0, _kinematicRadius, Air.Density, _viscosity);
                }

                if (SpinDecay != null)
                {
                    spinAcceleration = SpinDecay.SpinAcceleration(w, conditions);
                }
            }

            if (!acceleration.IsFinite || !spinAcceleration.IsFinite)
            {
                return ScaledDerivative(state);
            }

            return new StateDerivative(state.Velocity, acceleration, spinAcceleration);
        }

        // The same forces without spurious overflow: directions are unit vectors and magnitudes k s^2 C are products
        // of finite factors, infinite only when the true value exceeds double.MaxValue; a zero factor gives zero.
        [MethodImpl(MethodImplOptions.NoInlining)]
        internal StateDerivative ScaledDerivative(in FlightState state)
        {
            Vector3d w = state.AngularVelocity;
            Vector3d wind = _windVaries ? Air.WindAt(state.Position, Up) : _wind;
            Vector3d relative = state.Velocity - wind;
            double relativeScale = 1;
            if (!relative.IsFinite && wind.IsFinite)
            {
                relative = state.Velocity * 0.5 - wind * 0.5; // finite halves of a difference that overflowed
                relativeScale = 2;
            }

            double speed = relativeScale * relative.Length; // infinite only if the true speed exceeds double.MaxValue
            double spinRate = w.Length;
            Vector3d acceleration = Gravity;
            Vector3d spinAcceleration = default;
            AeroConditions conditions;
            if (speed > MinimumAerodynamicSpeed)
            {
                Vector3d direction = relative.NormalizedOrZero();
                // (w x v_hat) / |w| and |w x v_hat| from w scaled by its largest component (no overflow in the cross product).
                Vector3d liftAxis = default;
                double transverse = 0;
                double largest = w.MaxAbsComponent;
                if (largest > 0 && double.IsFinite(largest))
                {
                    var unit = new Vector3d(w.X / largest, w.Y / largest, w.Z / largest);
                    Vector3d cross = Vector3d.Cross(unit, direction);
                    liftAxis = cross / unit.Length;
                    transverse = cross.Length * largest;
                }

                conditions = new AeroConditions(speed, spinRate, transverse, _kinematicRadius, Air.Density, _viscosity);
                if (_hasAero)
                {
                    double pressure = Overflow.Multiply(Overflow.Multiply(_dragFactor, speed), speed); // k s^2
                    if (Drag != null)
                    {
                        double drag;
                        if (Drag is ISpinLinearDrag linear && !double.IsFinite(conditions.SpinParameter))
                        {
                            // S = r|w|/s overflowed: k s^2 slope S is k s slope r |w| (finite wherever the true drag is).
                            drag = Overflow.Add(
                                Overflow.Multiply(pressure, linear.CoefficientWithoutSpin(conditions)),
                                Overflow.Multiply(Overflow.Multiply(Overflow.Multiply(_dragFactor, speed), linear.SpinSlope * _kinematicRadius), spinRate));
                        }
                        else
                        {
                            drag = Overflow.Multiply(pressure, Drag.DragCoefficient(conditions));
                        }

                        acceleration = Overflow.Add(acceleration, Overflow.Multiply(direction, -drag));
                    }

                    if (Lift != null && spinRate > MinimumLiftSpinRate)
                    {
                        double lift = Overflow.Multiply(pressure, Lift.LiftCoefficient(conditions));
                        acceleration = Overflow.Add(acceleration, Overflow.Multiply(liftAxis, lift));
                    }
                }
            }
            else
            {
                conditions = new AeroConditions(0, spinRate, 0, _kinematicRadius, Air.Density, _viscosity);
            }

            if (SpinDecay != null)
            {
                spinAcceleration = SpinDecay.SpinAcceleration(w, conditions);
            }

            return new StateDerivative(state.Velocity, acceleration, spinAcceleration);
        }

        /// <summary>
        /// True when <see cref="StiffnessRate"/> over a step of <paramref name="step"/> s from <paramref name="state"/> is
        /// surely at most <paramref name="rateLimit"/> / step, judged from an upper bound of the rate that needs no law
        /// evaluation: 1.1 (2 k s_max (max|C_D| + max|C_L|) + max decay rate), s_max = s + |g| step, which is at least the
        /// rate in every branch of <see cref="StiffnessRate"/>. False when a law has no known bound or the bound is not
        /// below the limit (then the caller computes the rate). StableStepping asks it with half its limit, so the
        /// roundings of the two computations cannot change its substep count (one in both cases).
        /// </summary>
        internal bool StiffnessSurelyBelow(in FlightState state, double step, double rateLimit)
        {
            if (!(_coefficientBound >= 0))
            {
                return false;
            }

            double speed = (state.Velocity - (_windVaries ? Air.WindAt(state.Position, Up) : _wind)).Length;
            double fastest = speed + _gravityLength * step;
            double bound = 1.1 * (2 * _dragFactor * fastest * _coefficientBound + _decayRateBound);
            return step * bound <= rateLimit;
        }

        /// <summary>
        /// The stiffness rate sigma, 1/s, that StableStepping keeps h sigma under: the largest
        /// drag eigenvalue 2 k C_D s plus the Magnus rotation bound 2 k |C_L| s and the spin-decay rate, from this
        /// model's own laws and its own wind at the ball (a wind profile included), over the speeds the ball can reach
        /// within <paramref name="step"/> (s to s + |g| step). See StableStepping's remarks for the derivation.
        /// </summary>
        internal double StiffnessRate(in FlightState state, double step)
        {
            if (!_hasAero && SpinDecay == null)
            {
                return 0;
            }

            double speed = (state.Velocity - (_windVaries ? Air.WindAt(state.Position, Up) : _wind)).Length;
            double fastest = speed + Gravity.Length * step;
            // Within 10 % of the speed (the common case: g h is 0.04 m/s at 1/240 s) one evaluation at s_max with a 10 %
            // margin stands for both ends; otherwise both ends are evaluated.
            double rate = fastest <= 1.1 * speed
                ? 1.1 * StiffnessRateAt(state.AngularVelocity, fastest)
                : Math.Max(StiffnessRateAt(state.AngularVelocity, speed), StiffnessRateAt(state.AngularVelocity, fastest));
            return double.IsFinite(rate) ? rate : double.MaxValue;
        }

        // 2 k s (C_D + |C_L|) at air speed s with the whole spin taken as transverse (the most lift it can give), plus the
        // spin-decay rate |dw/dt| / |w| there.
        private double StiffnessRateAt(in Vector3d spin, double speed)
        {
            double spinRate = spin.Length;
            var conditions = new AeroConditions(speed, spinRate, spinRate, _kinematicRadius, Air.Density, _viscosity);
            double rate = 0;
            if (_hasAero && speed > 0)
            {
                double drag = Drag?.DragCoefficient(conditions) ?? 0;
                double lift = Lift != null && spinRate > MinimumLiftSpinRate ? Math.Abs(Lift.LiftCoefficient(conditions)) : 0;
                rate = 2 * _dragFactor * speed * (Math.Abs(drag) + lift);
            }

            if (SpinDecay != null && spinRate > 0)
            {
                rate += SpinDecay.SpinAcceleration(spin, conditions).Length / spinRate;
            }

            return rate;
        }

        /// <summary>
        /// Translational mechanical energy 1/2 m |v|^2 - m g . p, J (kinetic energy plus potential energy
        /// measured from the origin along gravity). Without wind, drag can only lower it and Magnus lift
        /// does no work. Never NaN for a finite state; finite whenever the energy fits in a double.
        /// </summary>
        /// <param name="state">The state.</param>
        internal double MechanicalEnergy(in FlightState state)
        {
            double energy = Ball.Mass * (0.5 * state.Velocity.LengthSquared - Vector3d.Dot(Gravity, state.Position));
            if (double.IsFinite(energy) || !state.IsFinite)
            {
                return energy;
            }

            // Scaled, term by term: finite when the energy fits in a double, never NaN (infinity minus infinity).
            double speed = state.Velocity.Length;
            double kinetic = Overflow.Multiply(Overflow.Multiply(0.5 * Ball.Mass, speed), speed);
            double potential = Overflow.Add(
                Overflow.Add(-Overflow.Multiply(Overflow.Multiply(Ball.Mass, Gravity.X), state.Position.X), -Overflow.Multiply(Overflow.Multiply(Ball.Mass, Gravity.Y), state.Position.Y)),
                -Overflow.Multiply(Overflow.Multiply(Ball.Mass, Gravity.Z), state.Position.Z));
            return Overflow.Add(kinetic, potential);
        }

        /// <summary>Rotational kinetic energy 1/2 I |w|^2, J (never NaN; infinite only beyond double.MaxValue).</summary>
        /// <param name="state">The state.</param>
        internal double RotationalEnergy(in FlightState state)
        {
            double energy = 0.5 * Ball.MomentOfInertia * state.AngularVelocity.LengthSquared;
            if (double.IsFinite(energy) || !state.AngularVelocity.IsFinite)
            {
                return energy;
            }

            double rate = state.AngularVelocity.Length;
            return Overflow.Multiply(Overflow.Multiply(0.5 * Ball.MomentOfInertia, rate), rate);
        }

        /// <inheritdoc />
        public override string ToString() =>
            $"FlightModel({Ball}, {Air}, g={Gravity}, drag={Drag?.ToString() ?? "off"}, lift={Lift?.ToString() ?? "off"}, " +
            $"spinDecay={SpinDecay?.ToString() ?? "off"})";
    }

    /// <summary>A count of <see cref="FlightModel.Derivative"/> calls (a test hook; see FlightModel.CountedEvaluations).</summary>
    internal sealed class EvaluationCount
    {
        /// <summary>Calls so far.</summary>
        public long Calls;

        /// <summary>Counts one call.</summary>
        public void Add() => Calls++;
    }
}
