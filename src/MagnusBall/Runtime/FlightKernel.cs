using System.Runtime.CompilerServices;
using MagnusBall.Aerodynamics;
using MagnusBall.Integration;
using DP = MagnusBall.Integration.DormandPrince54;

namespace MagnusBall
{
    /// <summary>
    /// The flight ODE specialised for one <see cref="FlightModel"/>'s coefficient laws: picked once when the model is
    /// built (<see cref="FlightKernelFactory"/>), then every derivative evaluation and every fixed step the built-in
    /// integrators take runs through it. One virtual call per evaluation, step or run; the laws themselves are inlined.
    /// </summary>
    internal abstract class FlightKernel
    {
        /// <summary>The test hook behind <see cref="FlightModel.CountedEvaluations"/>: null in every shipped use.</summary>
        internal EvaluationCount? Counter;

        /// <summary>What a drag or lift law that reads nothing (Reads == None: a constant coefficient) is given.</summary>
        private protected static readonly AeroConditions NoConditions = default;

        /// <summary>
        /// True under Mono and Unity's IL2CPP: take RK4's straight-line forms, for the thesis model's common case (see
        /// Rk4Straight) and for Stepanek's tennis laws folded in still air (Rk4StraightStepanek). RyuJIT keeps the chain in
        /// registers across the branches anyway, and measured the straight-line form 3-5 % slower; it folds this constant
        /// away. Both forms give the same bits. The flight core's event quick test, the dense output and the copy of RK4's
        /// end (FlightKernel's Deliver) pick their forms by it too (HermiteSegment.CannotFall, DormandPrince54Step). Compiled by Unity
        /// from the package's sources, it is Unity's own scripting-backend symbols (ENABLE_MONO, ENABLE_IL2CPP), fixed at
        /// compile time; the DLL built here asks the runtime for Mono's marker type instead, a reflection lookup that
        /// Unity's managed code stripping can break (Mono.Runtime is internal to the class library), which is why the
        /// package does not rely on it. Only speed depends on this, never the bits.
        /// </summary>
#if ENABLE_MONO || ENABLE_IL2CPP
        internal static readonly bool PreferStraightLine = CompiledForUnityBackend;

        /// <summary>Present only where Unity's backend symbols chose the forms above (checked by MagnusBall.Core.UnityCompile).</summary>
        internal const bool CompiledForUnityBackend = true;
#else
        internal static readonly bool PreferStraightLine = System.Type.GetType("Mono.Runtime") != null;
#endif

        // The range Stepanek's folded lift is taken in (|w| and s within 1e50 and 1e100 of 1, with k and r within 1e50 of 1:
        // FoldsLiftAtScale): no square or product of the fold's inputs overflows, none of the squares is subnormal, and the
        // scale k s / |w| stays within 1e200 of 1. The results may still underflow where the lift itself is below 1e-300 or
        // so (C_L of an extreme ratio of |w x v_rel| to s^2): the fold then keeps the tiny value the general formula's k C_L
        // loses to zero. Outside the range the general formula, as before. The ball batch's lanes take the same range.
        internal const double FoldMinimum = 1e-50, FoldMaximum = 1e50, FoldMinimumSquare = 1e-200, FoldMaximumSquare = 1e200;

        /// <summary>
        /// Where dw/dt = c w (<paramref name="factor"/> c, a constant), the magnitudes of RK4's stage spins over the step's
        /// spin w: the stage spins are w + h/2 c w = g2 w, w + h/2 c (g2 w) = g3 w and w + h c (g3 w) = g4 w, so f = |g| with
        /// g2 = 1 + h/2 c, g3 = 1 + h/2 (c g2), g4 = 1 + h (c g3). The ball batch forms the same.
        /// </summary>
        internal static void StageSpinFactors(double factor, double step, out double f2, out double f3, out double f4)
        {
            double half = 0.5 * step;
            double g2 = 1 + half * factor;
            double g3 = 1 + half * (factor * g2);
            double g4 = 1 + step * (factor * g3);
            f2 = System.Math.Abs(g2);
            f3 = System.Math.Abs(g3);
            f4 = System.Math.Abs(g4);
        }

        /// <summary>
        /// Whether a step is at most one time constant of dw/dt = c w (h |c| &lt;= 1), where every factor of
        /// <see cref="StageSpinFactors"/> is at least 1/4: the step-size half of the kernel's choice to scale RK4's stage spin
        /// rates (Rk4Loop), which the ball batch makes too.
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static bool WithinOneTimeConstant(double factor, double step) => step * System.Math.Abs(factor) <= 1;

        /// <summary>True where a model's k and r are within the fold's range (so its balls may take the folded lift).</summary>
        internal static bool FoldsLiftAtScale(double factor, double radius) =>
            factor >= FoldMinimum && factor <= FoldMaximum && radius >= FoldMinimum && radius <= FoldMaximum;

        /// <summary>The right-hand side at <paramref name="state"/> (bit for bit the general formula, except the folded forms of a constant lift and of Stepanek's lift: to rounding).</summary>
        internal abstract StateDerivative Derivative(in FlightState state);

        /// <summary>
        /// One classic RK4 step from <paramref name="state"/> with start derivative <paramref name="k1"/>: the state at
        /// state.Time + step and, in <paramref name="end"/>, the derivative there. Four evaluations (k2, k3, k4 and the
        /// end, which is the next step's k1). No argument checks: the caller checks.
        /// </summary>
        internal abstract FlightState RungeKutta4(in FlightState state, in StateDerivative k1, double step, out StateDerivative end);

        /// <summary>
        /// True where a law is the user's own (run through <see cref="InterfaceDrag"/>, <see cref="InterfaceLift"/> or
        /// <see cref="InterfaceSpinDecay"/>): the only code an evaluation runs that can throw.
        /// </summary>
        internal abstract bool RunsUserCode { get; }

        /// <summary>
        /// <see cref="RungeKutta4"/>, the same arithmetic, with the step's end written straight into
        /// <paramref name="next"/> and <paramref name="end"/> (the flight core passes its own fields: no struct is returned
        /// through a temporary and copied, so the fields are read back from the stores that wrote them).
        /// <paramref name="next"/> must not be a part of <paramref name="state"/> (it may be written before the state is
        /// read in full: under Mono, by the straight-line form's declined attempt); <paramref name="end"/> may be
        /// <paramref name="k1"/> (it is written last, after k1's last read; a caller's <c>out derivative</c> passed back in).
        /// No argument checks.
        /// </summary>
        internal abstract void RungeKutta4Into(in FlightState state, in StateDerivative k1, double step, out FlightState next, out StateDerivative end);

        /// <summary>
        /// Up to <paramref name="count"/> RK4 steps of <paramref name="step"/> seconds, in place: <paramref name="state"/> and
        /// <paramref name="derivative"/> (its derivative) are the start on entry and the end on return. Stops before a
        /// step whose end state or end derivative is not finite, leaving the last finite pair. Returns the steps taken
        /// (count, or fewer where it stopped). 4 evaluations a step (and the declined step's). No argument checks.
        /// </summary>
        internal abstract int RungeKutta4Advance(ref FlightState state, ref StateDerivative derivative, double step, int count);

        /// <summary>
        /// Test hook: RK4's straight-line form (see PreferStraightLine) whatever the runtime: the thesis model's common case
        /// (Rk4Straight), or Stepanek's drag and lift folded in still air (Rk4StraightStepanek). False where the model's laws
        /// or air are neither case or a stage leaves it (then end and endRates are not meaningful); true with the RK4 step
        /// and its end rates otherwise.
        /// </summary>
        internal abstract bool TryRk4StraightLine(in FlightState state, in StateDerivative k1, double step, out FlightState end, out StateDerivative endRates);

        /// <summary>One Heun step with its end derivative (2 evaluations). No argument checks.</summary>
        internal abstract FlightState Heun(in FlightState state, in StateDerivative k1, double step, out StateDerivative end);

        /// <summary>
        /// The six stages of one Dormand-Prince 5(4) step from <paramref name="state"/> with start derivative
        /// <paramref name="k1"/> (DormandPrince54's arithmetic term by term): the fifth-order end state and k2..k7, written
        /// into <paramref name="stages"/> in place as they are formed (k7 is the derivative at the end; what the stages held
        /// before is never read, and <paramref name="state"/> and <paramref name="k1"/> must not be parts of it). Six
        /// evaluations. No argument checks. False when a stage's acceleration or spin acceleration may not be finite (where
        /// FlightModel.Derivative would take its scaled path): the caller then redoes the step through FlightModel.Derivative.
        /// </summary>
        internal abstract bool DormandPrince54(in FlightState state, in StateDerivative k1, double step, ref DormandPrince54Stages stages);
    }

    /// <summary>The kernel for drag law <typeparamref name="TDrag"/>, lift law <typeparamref name="TLift"/> and spin decay <typeparamref name="TDecay"/>.</summary>
    internal sealed class FlightKernel<TDrag, TLift, TDecay> : FlightKernel
        where TDrag : struct, IDragLaw
        where TLift : struct, ILiftLaw
        where TDecay : struct, ISpinDecayLaw
    {
        private const AeroInputs SpinParameterBit = (AeroInputs)2;
        private const AeroInputs TransverseSpinParameterBit = (AeroInputs)8;

        private readonly TDrag _drag;
        private readonly TLift _lift;
        private readonly TDecay _decay;
        private readonly Vector3d _gravity;
        private readonly Vector3d _wind;
        private readonly Vector3d _up;
        private readonly Air _air;
        private readonly double _factor;
        private readonly double _radius;
        private readonly double _density;
        private readonly double _viscosity;
        private readonly bool _windVaries;
        private readonly bool _stillAir; // every wind component +0: v - wind is v itself
        private readonly bool _foldsLift; // k and r in the folded lift's range (FoldsStepanekLift)
        private readonly bool _scalesStageSpinRates; // Rk4Loop's stage spin rates may be scaled (still or uniform air, the fold's scale)
        private readonly double _kappaOverRadiusSquared; // StepanekTable.Kappa / r^2: z = Kappa s^2 / (r |w|)^2

        internal FlightKernel(FlightModel model, TDrag drag, TLift lift, TDecay decay)
        {
            _drag = drag;
            _lift = lift;
            _decay = decay;
            _gravity = model.Gravity;
            _air = model.Air;
            _wind = model.Air.Wind;
            _up = model.Up;
            _factor = model.AerodynamicFactor;
            _radius = model.Ball.Radius;
            _density = model.Air.Density;
            _viscosity = model.Air.DynamicViscosity;
            _windVaries = model.Air.WindProfile != null && model.Up.LengthSquared > 0;
            _stillAir = !_windVaries && IsPositiveZero(_wind.X) && IsPositiveZero(_wind.Y) && IsPositiveZero(_wind.Z);
            _foldsLift = FoldsLiftAtScale(_factor, _radius);
            _kappaOverRadiusSquared = StepanekTable.Kappa / (_radius * _radius);
            _scalesStageSpinRates = _foldsLift && !_windVaries;
        }

        private static bool IsPositiveZero(double x) => System.BitConverter.DoubleToInt64Bits(x) == 0;

        /// <summary>The drag, lift and spin-decay laws' type names, for tests and diagnostics.</summary>
        public override string ToString() => $"FlightKernel<{typeof(TDrag).Name}, {typeof(TLift).Name}, {typeof(TDecay).Name}>";

        // The acceleration and spin acceleration at (position, velocity, spin): FlightModel's formula, term by term in the
        // same order (so the bits agree), computing only the inputs some law reads. The Reads/IsPresent checks are
        // constants of the type parameters and fold away. Component by component (doubles, not Vector3d locals): the JIT
        // then keeps the evaluation chain (stage velocity, relative velocity, speed, acceleration) in registers instead of
        // storing each vector to the stack and reloading it, which put a store-to-load forwarding delay on every link of
        // RK4's dependent chain; Mono's JIT, which handles structs worse, gains the same way.
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private void Rates(
            in Vector3d position, double vx, double vy, double vz, in Vector3d spin, double spinRate, double inverseSpinRate,
            out Vector3d acceleration, out Vector3d spinAcceleration)
        {
            Counter?.Add();
            if (FoldsStepanekLift)
            {
                // Stepanek's lift: the folded form where it applies, else the general formula out of line, so that what is
                // inlined at each evaluation site stays small enough for the JIT to inline it (with the general code inline
                // too, Rates was no longer inlined into Rk4Loop, and every evaluation became a call).
                if (!_windVaries && TryFoldedRates(vx, vy, vz, spin, spinRate, out acceleration, out spinAcceleration))
                {
                    return;
                }

                // Through copies: a caller's variable passed by reference to a call that is not inlined would live in memory
                // on every path, the folded one too (a store and a load on RK4's dependent chain). The spin's own rates: an
                // RK4 stage may pass its rate scaled from the step's (Rk4Loop), which the general formula must not see.
                Vector3d at = position, around = spin;
                if (_decay.SpinOnly && _scalesStageSpinRates)
                {
                    SpinRates(spin.X, spin.Y, spin.Z, out spinRate, out inverseSpinRate);
                }

                OutOfLineRates(at, vx, vy, vz, around, spinRate, inverseSpinRate, out Vector3d generalAcceleration, out Vector3d generalSpinAcceleration);
                acceleration = generalAcceleration;
                spinAcceleration = generalSpinAcceleration;
                return;
            }

            GeneralRates(position, vx, vy, vz, spin, spinRate, inverseSpinRate, out acceleration, out spinAcceleration);
        }

        [MethodImpl(MethodImplOptions.NoInlining)]
        private void OutOfLineRates(
            in Vector3d position, double vx, double vy, double vz, in Vector3d spin, double spinRate, double inverseSpinRate,
            out Vector3d acceleration, out Vector3d spinAcceleration) =>
            GeneralRates(position, vx, vy, vz, spin, spinRate, inverseSpinRate, out acceleration, out spinAcceleration);

        // The rates with Stepanek's lift folded (StepanekLiftFold), in still air or a uniform wind. False, with nothing
        // meaningful written, where the fold's range does not hold (then the general formula).
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private bool TryFoldedRates(double vx, double vy, double vz, in Vector3d spin, double spinRate, out Vector3d acceleration, out Vector3d spinAcceleration)
        {
            acceleration = default;
            spinAcceleration = default;
            if (!(_foldsLift && spinRate >= FoldMinimum && spinRate <= FoldMaximum))
            {
                return false;
            }

            // v - wind, as GeneralRates forms it
            double rx = vx, ry = vy, rz = vz;
            if (!_stillAir)
            {
                rx = vx - _wind.X;
                ry = vy - _wind.Y;
                rz = vz - _wind.Z;
            }

            double wx = spin.X, wy = spin.Y, wz = spin.Z;
            double qx = wy * rz - wz * ry, qy = wz * rx - wx * rz, qz = wx * ry - wy * rx; // w x v_rel
            double squared = rx * rx + ry * ry + rz * rz;
            double transverseSquared = qx * qx + qy * qy + qz * qz;
            if (!(squared >= FoldMinimumSquare && squared <= FoldMaximumSquare &&
                (transverseSquared == 0 || (transverseSquared >= FoldMinimumSquare && transverseSquared <= FoldMaximumSquare))))
            {
                return false;
            }

            // Vector3d.LengthOf's value (its squares are a normal double here), and above MinimumAerodynamicSpeed.
            double speed = System.Math.Sqrt(squared);
            // What the laws that are not folded read: the lift is folded, and Stepanek's drag too (it forms its spin
            // parameter itself where its table declines), so for the tennis model no division by the speed here.
            AeroConditions conditions = FoldedConditions(speed, spinRate);
            double ax = _gravity.X, ay = _gravity.Y, az = _gravity.Z;
            double inverseSpinRate = 1.0 / spinRate; // the one division by the spin: k / |w| here, 1 / |w|^2 in the drag's z
            double liftScale = StepanekLiftFold(squared, transverseSquared, _radius, _factor * inverseSpinRate * speed);
            if (typeof(TDrag) == typeof(StepanekDragLaw))
            {
                // Stepanek's drag folded too: -k C_D s v_rel with C_D = 0.508 + G, summed as (g + 0.508 e + G e) + lift with
                // e = -k s v_rel, so the late G (the end of the drag's chain) meets one product and one sum. G is read from
                // z = Kappa s^2 / (r |w|)^2, one product after the squared speed ((Kappa / r^2) (1 / |w|)^2 is a normal double
                // here, r and |w| in [1e-50, 1e50], formed off the speed's path): the speed's square root runs beside G's
                // polynomial, not before it. The lift, whose chain (a square root and a division after |w x v_rel|^2) is now
                // the longer, is added last.
                double z = squared * (_kappaOverRadiusSquared * (inverseSpinRate * inverseSpinRate));
                double spinPart = StepanekDrag.SpinPartOfSquare(z, speed, spinRate, _radius);
                double scale = -_factor * speed;
                double ex = rx * scale, ey = ry * scale, ez = rz * scale;
                acceleration = new Vector3d(
                    (ax + ex * 0.508 + spinPart * ex) + qx * liftScale,
                    (ay + ey * 0.508 + spinPart * ey) + qy * liftScale,
                    (az + ez * 0.508 + spinPart * ez) + qz * liftScale);
            }
            else
            {
                if (_drag.IsPresent)
                {
                    double dragScale = -_factor * _drag.Coefficient(conditions) * speed;
                    ax += rx * dragScale;
                    ay += ry * dragScale;
                    az += rz * dragScale;
                }

                acceleration = new Vector3d(ax + qx * liftScale, ay + qy * liftScale, az + qz * liftScale);
            }

            if (_decay.IsPresent)
            {
                spinAcceleration = _decay.SpinAcceleration(spin, conditions);
            }

            return true;
        }

        // The general formula's rates (see Rates).
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private void GeneralRates(
            in Vector3d position, double vx, double vy, double vz, in Vector3d spin, double spinRate, double inverseSpinRate,
            out Vector3d acceleration, out Vector3d spinAcceleration)
        {
            double ax = _gravity.X, ay = _gravity.Y, az = _gravity.Z;
            spinAcceleration = default;
            bool aero = _drag.IsPresent || _lift.IsPresent;
            if (!aero && !_decay.IsPresent)
            {
                acceleration = new Vector3d(ax, ay, az);
                return;
            }

            double wx = spin.X, wy = spin.Y, wz = spin.Z;

            AeroInputs reads = _drag.Reads | _lift.Reads | _decay.Reads;
            bool readsTransverse = (reads & AeroInputs.TransverseSpinRate) != 0;
            bool readsS = (reads & SpinParameterBit) != 0;
            bool readsSPerp = (reads & TransverseSpinParameterBit) != 0;
            bool readsRe = (reads & AeroInputs.ReynoldsNumber) != 0;

            // v - wind; in still air (every wind component +0) v itself, which is the same number: x - (+0) == x for every
            // double x, -0 and NaN included.
            double rx = vx, ry = vy, rz = vz;
            if (_windVaries)
            {
                Vector3d wind = _air.WindAt(position, _up);
                rx = vx - wind.X;
                ry = vy - wind.Y;
                rz = vz - wind.Z;
            }
            else if (!_stillAir)
            {
                rx = vx - _wind.X;
                ry = vy - _wind.Y;
                rz = vz - _wind.Z;
            }

            if (reads == AeroInputs.None)
            {
                FoldedRates(rx, ry, rz, spin, spinRate, inverseSpinRate, ref ax, ref ay, ref az, ref spinAcceleration);
                acceleration = new Vector3d(ax, ay, az);
                return;
            }

            double speed = Vector3d.LengthOf(rx, ry, rz);
            if (speed > FlightModel.MinimumAerodynamicSpeed)
            {
                double cx = 0, cy = 0, cz = 0; // w x v_hat
                double transverse = 0;
                if (_lift.IsPresent || readsTransverse)
                {
                    // relative / speed (Vector3d's division: one reciprocal, three products), then Vector3d.Cross
                    double inverseSpeed = 1.0 / speed;
                    double dx = rx * inverseSpeed, dy = ry * inverseSpeed, dz = rz * inverseSpeed;
                    cx = wy * dz - wz * dy;
                    cy = wz * dx - wx * dz;
                    cz = wx * dy - wy * dx;
                    if (readsTransverse)
                    {
                        transverse = Vector3d.LengthOf(cx, cy, cz);
                    }
                }

                double inverse = readsS || readsSPerp ? _radius / speed : 0;
                var conditions = new AeroConditions(
                    speed,
                    spinRate,
                    transverse,
                    _radius,
                    _density,
                    readsS ? spinRate * inverse : 0,
                    readsSPerp ? transverse * inverse : 0,
                    readsRe ? _density * speed * 2 * _radius / _viscosity : 0);

                if (_drag.IsPresent)
                {
                    // F_D / m = -(rho A / 2m) C_D s v_rel  (thesis eq. 4-5)
                    double dragScale = -_factor * _drag.Coefficient(conditions) * speed;
                    ax += rx * dragScale;
                    ay += ry * dragScale;
                    az += rz * dragScale;
                }

                if (_lift.IsPresent && spinRate > FlightModel.MinimumLiftSpinRate)
                {
                    // F_M / m = (rho A / 2m) C_L s^2 (w x v_hat) / |w|  (transverse-spin form)
                    double liftScale = _factor * _lift.Coefficient(conditions) * speed * speed / spinRate;
                    ax += cx * liftScale;
                    ay += cy * liftScale;
                    az += cz * liftScale;
                }

                if (_decay.IsPresent)
                {
                    spinAcceleration = _decay.SpinAcceleration(spin, conditions);
                }
            }
            else if (_decay.IsPresent)
            {
                var still = new AeroConditions(0, spinRate, 0, _radius, _density, 0, 0, 0);
                spinAcceleration = _decay.SpinAcceleration(spin, still);
            }

            acceleration = new Vector3d(ax, ay, az);
        }

        /// <summary>
        /// True where the lift is Stepanek's and no other law reads the transverse spin: Rates then takes the folded lift
        /// (a constant of the type parameters; the check folds away).
        /// </summary>
        /// <remarks>
        /// A static readonly field, not a property: optimised code reads it as a constant without inlining anything, so the
        /// other kernels' evaluation sites spend none of the JIT's inlining budget on it (as a property, the thesis kernel's
        /// four inlined stages ran out of budget and its laws' getters became calls).
        /// </remarks>
        private static readonly bool FoldsStepanekLift =
            typeof(TLift) == typeof(StepanekLiftLaw) && ((default(TDrag).Reads | default(TDecay).Reads) & AeroInputs.TransverseSpinRate) == 0;

        /// <summary>
        /// Stepanek's lift in folded form: the factor that multiplies w x v_rel. With S_perp = r|w x v_hat|/s =
        /// r|w x v_rel|/s^2, the law's (k C_L s^2 / |w|) (w x v_hat) is (k s / |w|) C_L (w x v_rel) with
        /// C_L = r|w x v_rel| / (2.022 r|w x v_rel| + 0.981 s^2): no 1/s, no unit vector and one division, and the
        /// square root of |w x v_rel|^2 runs beside the speed's (RK4's dependent chain; docs/performance.md). Equal to the
        /// general formula to rounding (s^2 is the sum of squares, not the rounded speed squared), not bit for bit.
        /// </summary>
        /// <param name="speedSquared">|v_rel|^2.</param>
        /// <param name="transverseSquared">|w x v_rel|^2.</param>
        /// <param name="radius">r.</param>
        /// <param name="scale">k s / |w|.</param>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static double StepanekLiftFold(double speedSquared, double transverseSquared, double radius, double scale)
        {
            double rt = radius * System.Math.Sqrt(transverseSquared);
            return scale * rt / (2.022 * rt + 0.981 * speedSquared); // scale rt is formed beside the denominator
        }

        // Rates for laws that read no spin parameter (see Rates), from the air-relative velocity r: gravity already in a.
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private void FoldedRates(
            double rx, double ry, double rz, in Vector3d spin, double spinRate, double inverseSpinRate,
            ref double ax, ref double ay, ref double az, ref Vector3d spinAcceleration)
        {
            double wx = spin.X, wy = spin.Y, wz = spin.Z;
            double speed = Vector3d.LengthOf(rx, ry, rz);
            // No law reads a spin parameter (the thesis's constant coefficients): the same force with the algebra
            // folded, (rho A / 2m) C_L s^2 (w x v_hat) / |w| = ((rho A / 2m) C_L s / |w|) (w x v_rel), so no 1/s,
            // and 1/|w| once per step where the spin is constant. Where the lift acts, the speed is multiplied in last,
            // g + s ((-k C_D) v_rel + (k C_L / |w|) (w x v_rel)), so all but one product and one sum are computed while
            // its square root runs (RK4's dependent chain; docs/performance.md). Equal to the general formula to
            // rounding (FlightKernelTests: within 4 ulp of the largest term), not bit for bit; drag alone (no lift, or a
            // spin at or below FlightModel.MinimumLiftSpinRate) is the general formula's drag term, bit for bit.
            if (speed > FlightModel.MinimumAerodynamicSpeed)
            {
                var plain = new AeroConditions(speed, spinRate, 0, _radius, _density, 0, 0, 0);
                if (_lift.IsPresent && spinRate > FlightModel.MinimumLiftSpinRate)
                {
                    double liftScale = _factor * _lift.Coefficient(plain) * inverseSpinRate;
                    // (w x v_rel) liftScale, Vector3d.Cross's formula
                    double ux = (wy * rz - wz * ry) * liftScale;
                    double uy = (wz * rx - wx * rz) * liftScale;
                    double uz = (wx * ry - wy * rx) * liftScale;
                    if (_drag.IsPresent)
                    {
                        double dragScale = -_factor * _drag.Coefficient(plain);
                        ux = rx * dragScale + ux;
                        uy = ry * dragScale + uy;
                        uz = rz * dragScale + uz;
                    }

                    ax += speed * ux;
                    ay += speed * uy;
                    az += speed * uz;
                }
                else if (_drag.IsPresent)
                {
                    double dragScale = -_factor * _drag.Coefficient(plain) * speed;
                    ax += rx * dragScale;
                    ay += ry * dragScale;
                    az += rz * dragScale;
                }

                if (_decay.IsPresent)
                {
                    spinAcceleration = _decay.SpinAcceleration(spin, plain);
                }
            }
            else if (_decay.IsPresent)
            {
                spinAcceleration = _decay.SpinAcceleration(spin, new AeroConditions(0, spinRate, 0, _radius, _density, 0, 0, 0));
            }
        }

        // |w| where some law reads it or lift needs it (else 0), and 1/|w| where the folded lift uses it (else 0).
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private void SpinRates(double wx, double wy, double wz, out double spinRate, out double inverseSpinRate)
        {
            AeroInputs reads = _drag.Reads | _lift.Reads | _decay.Reads;
            spinRate = _lift.IsPresent || (reads & AeroInputs.SpinRate) != 0 ? Vector3d.LengthOf(wx, wy, wz) : 0;
            inverseSpinRate = reads == AeroInputs.None && _lift.IsPresent && spinRate > FlightModel.MinimumLiftSpinRate ? 1.0 / spinRate : 0;
        }

        internal override StateDerivative Derivative(in FlightState state)
        {
            Vector3d p = state.Position, v = state.Velocity, w = state.AngularVelocity;
            SpinRates(w.X, w.Y, w.Z, out double spinRate, out double inverseSpinRate);
            Rates(p, v.X, v.Y, v.Z, w, spinRate, inverseSpinRate, out Vector3d acceleration, out Vector3d spinAcceleration);
            return new StateDerivative(v, acceleration, spinAcceleration);
        }

        internal override FlightState RungeKutta4(in FlightState state, in StateDerivative k1, double step, out StateDerivative end)
        {
            RungeKutta4Into(state, k1, step, out FlightState next, out end);
            if (PreferStraightLine)
            {
                return next; // Mono: its plain copy is the faster (see Deliver)
            }

            return FlightState.CopyOf(next);
        }

        internal override bool RunsUserCode =>
            typeof(TDrag) == typeof(InterfaceDrag) || typeof(TLift) == typeof(InterfaceLift) || typeof(TDecay) == typeof(InterfaceSpinDecay);

        internal override void RungeKutta4Into(in FlightState state, in StateDerivative k1, double step, out FlightState next, out StateDerivative end) =>
            Rk4(state, k1, step, out next, out end);

        internal override int RungeKutta4Advance(ref FlightState state, ref StateDerivative derivative, double step, int count)
        {
            if (count <= 1)
            {
                return count == 1 ? AdvanceOne(ref state, ref derivative, step) : 0;
            }

            // The first step straight from the caller's pair (no copy of it), then two pairs of locals in turn: each step
            // writes the other pair (the outputs may not alias the inputs), so no state is copied between steps.
            Rk4(state, derivative, step, out FlightState a, out StateDerivative ka);
            if (!IsFinite(a, ka))
            {
                return 0;
            }

            int i = 1;
            for (; i + 1 < count; i += 2)
            {
                Rk4(a, ka, step, out FlightState b, out StateDerivative kb);
                if (!IsFinite(b, kb))
                {
                    break;
                }

                Rk4(b, kb, step, out a, out ka);
                if (!IsFinite(a, ka))
                {
                    Deliver(b, kb, ref state, ref derivative);
                    return i + 1;
                }
            }

            if (i + 1 == count)
            {
                Rk4(a, ka, step, out FlightState b, out StateDerivative kb);
                if (IsFinite(b, kb))
                {
                    Deliver(b, kb, ref state, ref derivative);
                    return count;
                }
            }

            Deliver(a, ka, ref state, ref derivative);
            return i;
        }

        // Advance of one step (a game's one step a frame), apart: one pair of locals, where the loop's frame holds two (Mono
        // zero-fills every struct local on entry). Thesis model under Mono: 480 calls of one step cost 212 ns a step through
        // the loop's frame, 199 ns through this one, against 143 ns in one call.
        [MethodImpl(MethodImplOptions.NoInlining)]
        private int AdvanceOne(ref FlightState state, ref StateDerivative derivative, double step)
        {
            Rk4(state, derivative, step, out FlightState a, out StateDerivative ka);
            if (!IsFinite(a, ka))
            {
                return 0;
            }

            Deliver(a, ka, ref state, ref derivative);
            return 1;
        }

        // The caller's pair from a step's end, just written number by number by the step. Under RyuJIT copied number by number
        // (FlightState.CopyOf: a plain copy's wide load waits for the step's stores to reach memory; with AdvanceOne, one
        // step a call went from 66 to 55 ns on the thesis model, docs/performance.md); under Mono the plain copy, which its
        // JIT makes faster (the copy by numbers measured about 10 ns a call slower there). The same bits either way.
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static void Deliver(in FlightState end, in StateDerivative endDerivative, ref FlightState state, ref StateDerivative derivative)
        {
            if (PreferStraightLine)
            {
                state = end;
                derivative = endDerivative;
            }
            else
            {
                state = FlightState.CopyOf(end);
                derivative = StateDerivative.CopyOf(endDerivative);
            }
        }

        // Every component of the state and its derivative finite (the derivative's velocity is the state's).
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static bool IsFinite(in FlightState y, in StateDerivative k) => y.IsFinite && k.Acceleration.IsFinite && k.AngularAcceleration.IsFinite;

        internal override bool TryRk4StraightLine(in FlightState state, in StateDerivative k1, double step, out FlightState end, out StateDerivative endRates)
        {
            if (StepanekStraightCase)
            {
                bool answers = ScalesStageSpins(step)
                    ? Rk4StraightStepanek<ScaledStageSpinRates>(state, k1, step, out end, out Vector3d a, out Vector3d s)
                    : Rk4StraightStepanek<OwnStageSpinRates>(state, k1, step, out end, out a, out s);
                endRates = new StateDerivative(end.Velocity, a, s);
                return answers;
            }

            bool applies = (_drag.Reads | _lift.Reads) == AeroInputs.None && StraightLineCase;
            end = default;
            Vector3d acceleration = default;
            bool taken = applies && Rk4Straight(state, k1, step, out end, out acceleration);
            endRates = new StateDerivative(end.Velocity, acceleration, default);
            return taken;
        }

        internal override FlightState Heun(in FlightState state, in StateDerivative k1, double step, out StateDerivative end)
        {
            // Heun.Step's arithmetic: k2 at state.Advance(k1, step), then the average of the slopes.
            Vector3d p = state.Position, v = state.Velocity, w = state.AngularVelocity;
            Vector3d v2 = Add(v, k1.Acceleration, step);
            Vector3d w2 = _decay.IsPresent ? Add(w, k1.AngularAcceleration, step) : w;
            Vector3d p2 = _windVaries ? Add(p, k1.Velocity, step) : p;
            SpinRates(w2.X, w2.Y, w2.Z, out double spin2, out double inverse2);
            Rates(p2, v2.X, v2.Y, v2.Z, w2, spin2, inverse2, out Vector3d a2, out Vector3d wd2);
            double half = 0.5 * step;
            var next = new FlightState(
                p + (k1.Velocity + v2) * half,
                v + (k1.Acceleration + a2) * half,
                w + (k1.AngularAcceleration + wd2) * half,
                state.Time + step);
            Vector3d np = next.Position, nv = next.Velocity, nw = next.AngularVelocity;
            SpinRates(nw.X, nw.Y, nw.Z, out double spin, out double inverse);
            Rates(np, nv.X, nv.Y, nv.Z, nw, spin, inverse, out Vector3d a, out Vector3d wd);
            end = new StateDerivative(nv, a, wd);
            return next;
        }

        internal override bool DormandPrince54(in FlightState state, in StateDerivative k1, double step, ref DormandPrince54Stages stages)
        {
            // DormandPrince54's arithmetic term by term (Dp54Stage forms each stage from k1 and the stages written so far).
            // One evaluation site (a loop over k2..k7), so the inlined laws appear once in the code; the stage positions are
            // formed only where the wind depends on the height, the stage spins only where the spin decays (otherwise every
            // stage spin is the start spin plus zero rates); the end state is formed in full. The rates go straight into the
            // caller's stages, no table of its own (a 432-byte table of k1..k6, zeroed on entry and copied out at the end,
            // cost 6-8 % of an adaptive step on .NET; docs/performance.md).
            double h = step;
            double check = 0; // the sum of every stage's rates: finite when each of them is (or spuriously not, on overflow)
            Vector3d w0 = state.AngularVelocity;
            SpinRates(w0.X, w0.Y, w0.Z, out double spinRate, out double inverseSpinRate); // the whole step's, when the spin is constant
            for (int stage = 1; ; stage++)
            {
                // stage 1..5: k2..k6; stage 6: the end, where k7 is evaluated
                Dp54Stage(k1, ref stages, stage, h, state, out Vector3d ps, out Vector3d vs, out Vector3d ws);
                bool end = stage == 6;
                if (_decay.IsPresent || end)
                {
                    SpinRates(ws.X, ws.Y, ws.Z, out spinRate, out inverseSpinRate);
                }

                Rates(ps, vs.X, vs.Y, vs.Z, ws, spinRate, inverseSpinRate, out Vector3d a, out Vector3d s);
                check += a.X + a.Y + a.Z + s.X + s.Y + s.Z;
                switch (stage)
                {
                    case 1:
                        stages.K2.Set(vs, a, s);
                        break;
                    case 2:
                        stages.K3.Set(vs, a, s);
                        break;
                    case 3:
                        stages.K4.Set(vs, a, s);
                        break;
                    case 4:
                        stages.K5.Set(vs, a, s);
                        break;
                    case 5:
                        stages.K6.Set(vs, a, s);
                        break;
                    default:
                        stages.End = new FlightState(ps, vs, ws, state.Time + h);
                        stages.K7 = new StateDerivative(vs, a, s);
                        return double.IsFinite(check);
                }
            }
        }

        // Stage `stage` of Dormand-Prince 5(4) (1..5: the states of k2..k6; 6: the fifth-order end): y + (h a_i1) k1 +
        // (h a_i2) k2 + ..., left to right as DormandPrince54's Combine sums it (stage 1 as FlightState.Advance(k1, a21 h));
        // the end leaves k2 out (b2 = 0), as there. k2..k6 are read from the stages written so far. Not inlined: one small
        // copy serves the loop above.
        [MethodImpl(MethodImplOptions.NoInlining)]
        private void Dp54Stage(in StateDerivative k1, ref DormandPrince54Stages k, int stage, double h, in FlightState y, out Vector3d ps, out Vector3d vs, out Vector3d ws)
        {
            bool spins = _decay.IsPresent, positions = _windVaries;
            Vector3d p = y.Position, v = y.Velocity, w = y.AngularVelocity;
            ps = p;
            ws = w;
            switch (stage)
            {
                case 1:
                {
                    double c = DP.A21 * h;
                    vs = Add(v, k1.Acceleration, c);
                    if (spins)
                    {
                        ws = Add(w, k1.AngularAcceleration, c);
                    }

                    if (positions)
                    {
                        ps = Add(p, k1.Velocity, c);
                    }

                    return;
                }

                case 2:
                {
                    double ha = h * DP.A31, hb = h * DP.A32;
                    vs = Add(Add(v, k1.Acceleration, ha), k.K2.Acceleration, hb);
                    if (spins)
                    {
                        ws = Add(Add(w, k1.AngularAcceleration, ha), k.K2.AngularAcceleration, hb);
                    }

                    if (positions)
                    {
                        ps = Add(Add(p, k1.Velocity, ha), k.K2.Velocity, hb);
                    }

                    return;
                }

                case 3:
                {
                    double ha = h * DP.A41, hb = h * DP.A42, hc = h * DP.A43;
                    vs = Add(Add(Add(v, k1.Acceleration, ha), k.K2.Acceleration, hb), k.K3.Acceleration, hc);
                    if (spins)
                    {
                        ws = Add(Add(Add(w, k1.AngularAcceleration, ha), k.K2.AngularAcceleration, hb), k.K3.AngularAcceleration, hc);
                    }

                    if (positions)
                    {
                        ps = Add(Add(Add(p, k1.Velocity, ha), k.K2.Velocity, hb), k.K3.Velocity, hc);
                    }

                    return;
                }

                case 4:
                {
                    double ha = h * DP.A51, hb = h * DP.A52, hc = h * DP.A53, hd = h * DP.A54;
                    vs = Add(Add(Add(Add(v, k1.Acceleration, ha), k.K2.Acceleration, hb), k.K3.Acceleration, hc), k.K4.Acceleration, hd);
                    if (spins)
                    {
                        ws = Add(Add(Add(Add(w, k1.AngularAcceleration, ha), k.K2.AngularAcceleration, hb), k.K3.AngularAcceleration, hc), k.K4.AngularAcceleration, hd);
                    }

                    if (positions)
                    {
                        ps = Add(Add(Add(Add(p, k1.Velocity, ha), k.K2.Velocity, hb), k.K3.Velocity, hc), k.K4.Velocity, hd);
                    }

                    return;
                }

                case 5:
                {
                    double ha = h * DP.A61, hb = h * DP.A62, hc = h * DP.A63, hd = h * DP.A64, he = h * DP.A65;
                    vs = Add(Add(Add(Add(Add(v, k1.Acceleration, ha), k.K2.Acceleration, hb), k.K3.Acceleration, hc), k.K4.Acceleration, hd), k.K5.Acceleration, he);
                    if (spins)
                    {
                        ws = Add(Add(Add(Add(Add(w, k1.AngularAcceleration, ha), k.K2.AngularAcceleration, hb), k.K3.AngularAcceleration, hc), k.K4.AngularAcceleration, hd), k.K5.AngularAcceleration, he);
                    }

                    if (positions)
                    {
                        ps = Add(Add(Add(Add(Add(p, k1.Velocity, ha), k.K2.Velocity, hb), k.K3.Velocity, hc), k.K4.Velocity, hd), k.K5.Velocity, he);
                    }

                    return;
                }

                default:
                {
                    double ha = h * DP.B1, hc = h * DP.B3, hd = h * DP.B4, he = h * DP.B5, hf = h * DP.B6;
                    vs = Add(Add(Add(Add(Add(v, k1.Acceleration, ha), k.K3.Acceleration, hc), k.K4.Acceleration, hd), k.K5.Acceleration, he), k.K6.Acceleration, hf);
                    ws = Add(Add(Add(Add(Add(w, k1.AngularAcceleration, ha), k.K3.AngularAcceleration, hc), k.K4.AngularAcceleration, hd), k.K5.AngularAcceleration, he), k.K6.AngularAcceleration, hf);
                    ps = Add(Add(Add(Add(Add(p, k1.Velocity, ha), k.K3.Velocity, hc), k.K4.Velocity, hd), k.K5.Velocity, he), k.K6.Velocity, hf);
                    return;
                }
            }
        }

        // One RK4 step, RungeKutta4.Step's arithmetic term by term (except the inner stages' spin rates under an exponential
        // decay with Stepanek's lift folded, scaled from the step's in Rk4Loop, to rounding), plus the end rates, in one of two
        // shapes with the same arithmetic. The stage positions are formed only when the wind depends on the height (no law reads the position
        // otherwise), the stage spins only when the spin decays (otherwise its rate is zero and every stage spin equals the
        // start spin). The velocities, on the dependent chain from one stage's slope to the next, are kept component by
        // component so that the chain stays in registers.
        // - Laws that read no spin parameter (the folded form: constant coefficients, or none): the four evaluations
        //   written out (Rk4Unrolled). Their evaluation is a dozen operations, so four copies are small, and straight-line
        //   code lets the JIT keep the chain in registers (the loop spilled each stage's slope to the stack and reloaded
        //   it: 0.86x against 0.74x the thesis-style step, ratios in one run, docs/performance.md).
        // - Every other kernel: one evaluation site, a loop over the four evaluations k2, k3, k4 and the end (Rk4Loop), so
        //   the inlined laws appear once in the code (four inlined copies of Stepanek's laws made a 6 kB method with a
        //   1.6 kB stack frame, and were measured slower).
        // - Under Mono, the thesis model's common case first takes the straight-line form (Rk4Straight), here rather than
        //   inside Rk4Unrolled, whose large frame Mono zeroes on every call; and Stepanek's tennis laws folded in still air
        //   take theirs (Rk4StraightStepanek) before Rk4Loop. A straight-line form that declines leaves end untouched (its
        //   caller may pass k1 as end), and Rk4Loop or Rk4Unrolled takes the step.
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private void Rk4(in FlightState state, in StateDerivative k1, double step, out FlightState next, out StateDerivative end)
        {
            if ((_drag.Reads | _lift.Reads | _decay.Reads) != AeroInputs.None)
            {
                // The stage spin rates scaled where they may be (see Rk4Loop), as a type argument: each instantiation's
                // branches fold away (a run-time flag left them in the loop: about 4 % of the full tennis model's step).
                bool scales = ScalesStageSpins(step);
                if (PreferStraightLine && StepanekStraightCase && Counter is null)
                {
                    Vector3d straightAcceleration, straightSpinAcceleration;
                    if (scales
                        ? Rk4StraightStepanek<ScaledStageSpinRates>(state, k1, step, out next, out straightAcceleration, out straightSpinAcceleration)
                        : Rk4StraightStepanek<OwnStageSpinRates>(state, k1, step, out next, out straightAcceleration, out straightSpinAcceleration))
                    {
                        end = new StateDerivative(next.Velocity, straightAcceleration, straightSpinAcceleration);
                        return;
                    }
                }

                if (scales)
                {
                    Rk4Loop<ScaledStageSpinRates>(state, k1, step, out next, out end);
                }
                else
                {
                    Rk4Loop<OwnStageSpinRates>(state, k1, step, out next, out end);
                }

                return;
            }

            if (PreferStraightLine && StraightLineCase && Counter is null && Rk4Straight(state, k1, step, out next, out Vector3d endAcceleration))
            {
                end = new StateDerivative(next.Velocity, endAcceleration, default);
                return;
            }

            Rk4Unrolled(state, k1, step, out next, out end);
        }

        private void Rk4Unrolled(in FlightState state, in StateDerivative k1, double step, out FlightState next, out StateDerivative end)
        {
            double half = 0.5 * step;
            double sixth = step / 6.0;
            bool spins = _decay.IsPresent;
            bool positions = _windVaries;
            Vector3d p = state.Position, w = state.AngularVelocity;
            double vx = state.Velocity.X, vy = state.Velocity.Y, vz = state.Velocity.Z;
            Vector3d k1a = k1.Acceleration, k1s = k1.AngularAcceleration;
            SpinRates(w.X, w.Y, w.Z, out double spinRate, out double inverseSpinRate); // the whole step's, when the spin is constant

            // k2 at y + h/2 k1
            double v2x = vx + half * k1a.X, v2y = vy + half * k1a.Y, v2z = vz + half * k1a.Z;
            Vector3d w2 = spins ? Add(w, k1s, half) : w;
            Vector3d p2 = positions ? new Vector3d(p.X + half * vx, p.Y + half * vy, p.Z + half * vz) : p;
            Stage(p2, v2x, v2y, v2z, w2, ref spinRate, ref inverseSpinRate, out Vector3d a2, out Vector3d s2);

            // k3 at y + h/2 k2
            double v3x = vx + half * a2.X, v3y = vy + half * a2.Y, v3z = vz + half * a2.Z;
            Vector3d w3 = spins ? Add(w, s2, half) : w;
            Vector3d p3 = positions ? new Vector3d(p.X + half * v2x, p.Y + half * v2y, p.Z + half * v2z) : p;
            Stage(p3, v3x, v3y, v3z, w3, ref spinRate, ref inverseSpinRate, out Vector3d a3, out Vector3d s3);

            // k4 at y + h k3
            double v4x = vx + step * a3.X, v4y = vy + step * a3.Y, v4z = vz + step * a3.Z;
            Vector3d w4 = spins ? Add(w, s3, step) : w;
            Vector3d p4 = positions ? new Vector3d(p.X + step * v3x, p.Y + step * v3y, p.Z + step * v3z) : p;
            Stage(p4, v4x, v4y, v4z, w4, ref spinRate, ref inverseSpinRate, out Vector3d a4, out Vector3d s4);

            // y + (k1 + 2 (k2 + k3) + k4) h/6, grouped as RungeKutta4 groups it, and the end rates
            Vector3d k1v = k1.Velocity;
            Vector3d pe = EndPosition(p, k1v, v2x, v2y, v2z, v3x, v3y, v3z, v4x, v4y, v4z, sixth);
            double vex = vx + (k1a.X + (a2.X + a3.X) * 2.0 + a4.X) * sixth;
            double vey = vy + (k1a.Y + (a2.Y + a3.Y) * 2.0 + a4.Y) * sixth;
            double vez = vz + (k1a.Z + (a2.Z + a3.Z) * 2.0 + a4.Z) * sixth;
            Vector3d we = spins ? w + (k1s + 2.0 * (s2 + s3) + s4) * sixth : w + k1s * sixth;
            double time = state.Time + step;
            Stage(pe, vex, vey, vez, we, ref spinRate, ref inverseSpinRate, out Vector3d endAcceleration, out Vector3d endSpinAcceleration);
            var ve = new Vector3d(vex, vey, vez);
            next = new FlightState(pe, ve, we, time);
            end = new StateDerivative(ve, endAcceleration, endSpinAcceleration);
        }

        // The laws and air Rk4Straight is written for (with laws that read nothing): drag and lift, no spin decay, still air.
        private bool StraightLineCase
        {
            [MethodImpl(MethodImplOptions.AggressiveInlining)] // Mono inlines only tiny methods without it
            get => _drag.IsPresent && _lift.IsPresent && !_decay.IsPresent && _stillAir;
        }

        // Rk4Unrolled's arithmetic, operation for operation, for constant drag and lift, a constant spin, still air and
        // no evaluation counter, as one basic block: the branches of every evaluation (the counter, the wind,
        // Vector3d.LengthOf's range test, the minimum speed, the lift's spin test) become one test at the end (a state
        // without lift is declined first). Mono's JIT keeps no double in a register from one basic block to the next, so
        // there every branch stored and reloaded the whole dependent chain (docs/performance.md). False, with end written
        // but not meaningful (it is the caller's next state, so it must not be a part of state), where a stage leaves the common case (a speed at or below
        // FlightModel.MinimumAerodynamicSpeed, a squared speed past double.MaxValue, a spin rate at or below
        // FlightModel.MinimumLiftSpinRate): Rk4Unrolled then takes the step its own way. Where it answers true, the result is Rk4Unrolled's bit for bit
        // (FlightKernelTests.StraightLineRk4_OnAdversarialStates_IsTheGeneralStep_BitForBit: the same steps on a model with
        // a counter attached, which takes the general code). The stages are written out, as in Rk4Unrolled: a shared stage
        // method would hand its results back through out parameters, which Mono keeps in memory.
        private bool Rk4Straight(in FlightState state, in StateDerivative k1, double step, out FlightState end, out Vector3d endAcceleration)
        {
            double half = 0.5 * step;
            double sixth = step / 6.0;
            Vector3d p = state.Position, w = state.AngularVelocity;
            double wx = w.X, wy = w.Y, wz = w.Z;
            double spinRate = Vector3d.LengthOf(wx, wy, wz);
            if (!(spinRate > FlightModel.MinimumLiftSpinRate))
            {
                // No lift (no spin, or at most FlightModel.MinimumLiftSpinRate): known before the chain starts, so the general
                // step is not paid on top of this one.
                end = default;
                endAcceleration = default;
                return false;
            }

            double inverseSpinRate = 1.0 / spinRate;
            // FoldedRates' -_factor C_D and _factor C_L (1/|w|), the same products (left to right).
            double dragFactor = -_factor * _drag.Coefficient(NoConditions);
            double liftFactor = _factor * _lift.Coefficient(NoConditions) * inverseSpinRate;
            double gx = _gravity.X, gy = _gravity.Y, gz = _gravity.Z;
            double vx = state.Velocity.X, vy = state.Velocity.Y, vz = state.Velocity.Z;
            Vector3d k1a = k1.Acceleration;
            bool common = true;

            // k2 at y + h/2 k1
            double v2x = vx + half * k1a.X, v2y = vy + half * k1a.Y, v2z = vz + half * k1a.Z;
            double squared = v2x * v2x + v2y * v2y + v2z * v2z;
            double speed = System.Math.Sqrt(squared);
            common &= squared <= double.MaxValue & speed > FlightModel.MinimumAerodynamicSpeed;
            double u2x = v2x * dragFactor + (wy * v2z - wz * v2y) * liftFactor;
            double u2y = v2y * dragFactor + (wz * v2x - wx * v2z) * liftFactor;
            double u2z = v2z * dragFactor + (wx * v2y - wy * v2x) * liftFactor;
            double a2x = gx + speed * u2x, a2y = gy + speed * u2y, a2z = gz + speed * u2z;

            // k3 at y + h/2 k2
            double v3x = vx + half * a2x, v3y = vy + half * a2y, v3z = vz + half * a2z;
            squared = v3x * v3x + v3y * v3y + v3z * v3z;
            speed = System.Math.Sqrt(squared);
            common &= squared <= double.MaxValue & speed > FlightModel.MinimumAerodynamicSpeed;
            double u3x = v3x * dragFactor + (wy * v3z - wz * v3y) * liftFactor;
            double u3y = v3y * dragFactor + (wz * v3x - wx * v3z) * liftFactor;
            double u3z = v3z * dragFactor + (wx * v3y - wy * v3x) * liftFactor;
            double a3x = gx + speed * u3x, a3y = gy + speed * u3y, a3z = gz + speed * u3z;

            // k4 at y + h k3
            double v4x = vx + step * a3x, v4y = vy + step * a3y, v4z = vz + step * a3z;
            squared = v4x * v4x + v4y * v4y + v4z * v4z;
            speed = System.Math.Sqrt(squared);
            common &= squared <= double.MaxValue & speed > FlightModel.MinimumAerodynamicSpeed;
            double u4x = v4x * dragFactor + (wy * v4z - wz * v4y) * liftFactor;
            double u4y = v4y * dragFactor + (wz * v4x - wx * v4z) * liftFactor;
            double u4z = v4z * dragFactor + (wx * v4y - wy * v4x) * liftFactor;
            double a4x = gx + speed * u4x, a4y = gy + speed * u4y, a4z = gz + speed * u4z;

            // y + (k1 + 2 (k2 + k3) + k4) h/6, and the end rates
            Vector3d k1v = k1.Velocity;
            Vector3d pe = EndPosition(p, k1v, v2x, v2y, v2z, v3x, v3y, v3z, v4x, v4y, v4z, sixth);
            double vex = vx + (k1a.X + (a2x + a3x) * 2.0 + a4x) * sixth;
            double vey = vy + (k1a.Y + (a2y + a3y) * 2.0 + a4y) * sixth;
            double vez = vz + (k1a.Z + (a2z + a3z) * 2.0 + a4z) * sixth;
            // The end rates at the end spin w + k1's spin rate h/6, as Rk4Unrolled evaluates them (with the start's |w|):
            // not w itself, which differs from it in the sign of a zero component (-0 + 0 is +0) and for a k1 whose spin
            // rate is not zero.
            Vector3d we = w + k1.AngularAcceleration * sixth;
            double ex = we.X, ey = we.Y, ez = we.Z;
            squared = vex * vex + vey * vey + vez * vez;
            speed = System.Math.Sqrt(squared);
            common &= squared <= double.MaxValue & speed > FlightModel.MinimumAerodynamicSpeed;
            endAcceleration = new Vector3d(
                gx + speed * (vex * dragFactor + (ey * vez - ez * vey) * liftFactor),
                gy + speed * (vey * dragFactor + (ez * vex - ex * vez) * liftFactor),
                gz + speed * (vez * dragFactor + (ex * vey - ey * vex) * liftFactor));
            end = new FlightState(pe, new Vector3d(vex, vey, vez), we, state.Time + step);
            return common;
        }

        // Under an exponential decay, what Rk4Loop<ScaledStageSpinRates> (and its straight-line form) forms ahead of the
        // velocity's stages: the stage spin factors, the end spin (the loop's expression: s23 = s2 + s3, sk = s4, the same
        // bits) and its own rates.
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private void ScaledStageSpins(
            in Vector3d w, in Vector3d s1, double step, out double f2, out double f3, out double f4, out Vector3d endSpin,
            out double endRate, out double endInverse)
        {
            double half = 0.5 * step;
            double sixth = step / 6.0;
            StageSpinFactors(_decay.SpinFactor, step, out f2, out f3, out f4);
            Vector3d s2 = _decay.SpinAcceleration(Add(w, s1, half), NoConditions);
            Vector3d s3 = _decay.SpinAcceleration(Add(w, s2, half), NoConditions);
            Vector3d s4 = _decay.SpinAcceleration(Add(w, s3, step), NoConditions);
            endSpin = w + (s1 + 2.0 * (s2 + s3) + s4) * sixth;
            SpinRates(endSpin.X, endSpin.Y, endSpin.Z, out endRate, out endInverse);
        }

        // The end position y + (k1 + 2 (k2 + k3) + k4) h/6 from the stage velocities, grouped as RungeKutta4 groups it (the
        // written-out steps' common tail: Rk4Unrolled, Rk4Straight, Rk4StraightStepanek).
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static Vector3d EndPosition(
            in Vector3d p, in Vector3d k1v, double v2x, double v2y, double v2z, double v3x, double v3y, double v3z,
            double v4x, double v4y, double v4z, double sixth) =>
            new Vector3d(
                p.X + (k1v.X + (v2x + v3x) * 2.0 + v4x) * sixth,
                p.Y + (k1v.Y + (v2y + v3y) * 2.0 + v4y) * sixth,
                p.Z + (k1v.Z + (v2z + v3z) * 2.0 + v4z) * sixth);

        // Whether an RK4 step of this size takes its inner stages' spin rates scaled from the step's (see Rk4Loop).
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private bool ScalesStageSpins(double step) =>
            FoldsStepanekLift && _decay.SpinOnly && _scalesStageSpinRates && WithinOneTimeConstant(_decay.SpinFactor, step);

        // The laws and air Rk4StraightStepanek is written for: Stepanek's drag and lift, both folded (TryFoldedRates), any
        // spin decay, still air.
        private bool StepanekStraightCase
        {
            [MethodImpl(MethodImplOptions.AggressiveInlining)]
            get => typeof(TDrag) == typeof(StepanekDragLaw) && FoldsStepanekLift && _foldsLift && _stillAir;
        }

        // Rk4Loop's arithmetic, operation for operation, for Stepanek's drag and lift folded in still air with no evaluation
        // counter (the tennis model and its presets), as one basic block under Mono, as Rk4Straight is for the thesis model:
        // the branches of every evaluation (the fold's ranges, the table's row) become flags tested once at the end, and a
        // stage spin's LengthOf loses its branch (see StraightLength). False, with next written but not meaningful, where a
        // stage leaves that case (a spin rate, squared speed or squared |w x v| outside the fold's range, z outside the
        // table); the caller then takes Rk4Loop, which gives the general formula there. A start spin outside the fold's
        // range is declined before the chain starts.
        // Like Rk4Straight it hands back the end rates as two vectors, and the caller forms the end derivative only where it
        // answers: the caller's end derivative may be its k1 (IIntegrator.Step's callers pass one variable for both), which
        // a declined step must leave as it was for the general step.
        private bool Rk4StraightStepanek<TStages>(
            in FlightState state, in StateDerivative k1, double step, out FlightState next, out Vector3d endAcceleration,
            out Vector3d endSpinAcceleration)
            where TStages : struct, IStageSpinRates
        {
            bool scaled = default(TStages).Scaled;
            bool spins = _decay.IsPresent;
            Vector3d p = state.Position, w = state.AngularVelocity;
            double startRate = Vector3d.LengthOf(w.X, w.Y, w.Z); // SpinRates' |w| (the lift is present)
            if (!(startRate >= FoldMinimum && startRate <= FoldMaximum))
            {
                next = default;
                endAcceleration = default;
                endSpinAcceleration = default;
                return false;
            }

            double half = 0.5 * step;
            double sixth = step / 6.0;
            double f2 = 0, f3 = 0, f4 = 0, endRate = 0;
            Vector3d endSpin = default;
            if (scaled)
            {
                ScaledStageSpins(w, k1.AngularAcceleration, step, out f2, out f3, out f4, out endSpin, out endRate, out _);
            }

            double vx = state.Velocity.X, vy = state.Velocity.Y, vz = state.Velocity.Z;
            Vector3d k1a = k1.Acceleration, k1s = k1.AngularAcceleration;
            bool common = true;

            // k2 at y + h/2 k1
            double v2x = vx + half * k1a.X, v2y = vy + half * k1a.Y, v2z = vz + half * k1a.Z;
            Vector3d w2 = spins ? Add(w, k1s, half) : w;
            double rate2 = scaled ? startRate * f2 : spins ? StraightLength(w2) : startRate;
            StraightStepanekRates(v2x, v2y, v2z, w2, rate2, ref common, out double a2x, out double a2y, out double a2z, out Vector3d s2);

            // k3 at y + h/2 k2
            double v3x = vx + half * a2x, v3y = vy + half * a2y, v3z = vz + half * a2z;
            Vector3d w3 = spins ? Add(w, s2, half) : w;
            double rate3 = scaled ? startRate * f3 : spins ? StraightLength(w3) : startRate;
            StraightStepanekRates(v3x, v3y, v3z, w3, rate3, ref common, out double a3x, out double a3y, out double a3z, out Vector3d s3);

            // k4 at y + h k3
            double v4x = vx + step * a3x, v4y = vy + step * a3y, v4z = vz + step * a3z;
            Vector3d w4 = spins ? Add(w, s3, step) : w;
            double rate4 = scaled ? startRate * f4 : spins ? StraightLength(w4) : startRate;
            StraightStepanekRates(v4x, v4y, v4z, w4, rate4, ref common, out double a4x, out double a4y, out double a4z, out Vector3d s4);

            // y + (k1 + 2 (k2 + k3) + k4) h/6, grouped as Rk4Loop groups it, and the end rates
            Vector3d k1v = k1.Velocity;
            Vector3d pe = EndPosition(p, k1v, v2x, v2y, v2z, v3x, v3y, v3z, v4x, v4y, v4z, sixth);
            double vex = vx + (k1a.X + (a2x + a3x) * 2.0 + a4x) * sixth;
            double vey = vy + (k1a.Y + (a2y + a3y) * 2.0 + a4y) * sixth;
            double vez = vz + (k1a.Z + (a2z + a3z) * 2.0 + a4z) * sixth;
            Vector3d we = scaled ? endSpin : spins ? w + (k1s + 2.0 * (s2 + s3) + s4) * sixth : w + k1s * sixth;
            double rateEnd = scaled ? endRate : spins ? StraightLength(we) : startRate;
            StraightStepanekRates(vex, vey, vez, we, rateEnd, ref common, out double aex, out double aey, out double aez, out endSpinAcceleration);
            next = new FlightState(pe, new Vector3d(vex, vey, vez), we, state.Time + step);
            endAcceleration = new Vector3d(aex, aey, aez);
            return common;
        }

        // Vector3d.LengthOf's common path, without its branch. Where LengthOf would take its scaled path instead (a square
        // that is 0, subnormal, past double.MaxValue or NaN), this rate is below 1.5e-154, infinite or NaN, and the fold's
        // spin-rate range, which StraightStepanekRates tests on every stage's rate, declines the step: no flag of its own.
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static double StraightLength(in Vector3d w) => System.Math.Sqrt(w.X * w.X + w.Y * w.Y + w.Z * w.Z);

        // TryFoldedRates for Stepanek's drag and lift in still air, operation for operation, without a branch: common cleared
        // where TryFoldedRates would decline or the table would (the results are then of no meaning).
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private void StraightStepanekRates(
            double rx, double ry, double rz, in Vector3d spin, double spinRate, ref bool common,
            out double ax, out double ay, out double az, out Vector3d spinAcceleration)
        {
            double wx = spin.X, wy = spin.Y, wz = spin.Z;
            double qx = wy * rz - wz * ry, qy = wz * rx - wx * rz, qz = wx * ry - wy * rx; // w x v_rel
            double squared = rx * rx + ry * ry + rz * rz;
            double transverseSquared = qx * qx + qy * qy + qz * qz;
            common &= spinRate >= FoldMinimum & spinRate <= FoldMaximum & squared >= FoldMinimumSquare & squared <= FoldMaximumSquare &
                (transverseSquared == 0 | (transverseSquared >= FoldMinimumSquare & transverseSquared <= FoldMaximumSquare));
            double speed = System.Math.Sqrt(squared);
            double inverseSpinRate = 1.0 / spinRate;
            double liftScale = StepanekLiftFold(squared, transverseSquared, _radius, _factor * inverseSpinRate * speed);
            double z = squared * (_kappaOverRadiusSquared * (inverseSpinRate * inverseSpinRate));
            double spinPart = StepanekDrag.TableWithoutBranch(z, out bool inTable);
            common &= inTable;
            double scale = -_factor * speed;
            double ex = rx * scale, ey = ry * scale, ez = rz * scale;
            ax = (_gravity.X + ex * 0.508 + spinPart * ex) + qx * liftScale;
            ay = (_gravity.Y + ey * 0.508 + spinPart * ey) + qy * liftScale;
            az = (_gravity.Z + ez * 0.508 + spinPart * ez) + qz * liftScale;
            // (A law of the spin and the speed alone, as both built-in decays are, is given the speed instead of the conditions.)
            spinAcceleration = _decay.SpeedOnly ? _decay.SpinAccelerationAtSpeed(spin, speed)
                : _decay.IsPresent ? _decay.SpinAcceleration(spin, FoldedConditions(speed, spinRate)) : default;
        }

        // The conditions TryFoldedRates gives the laws it does not fold (the spin decay, where Stepanek's drag is folded).
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private AeroConditions FoldedConditions(double speed, double spinRate)
        {
            AeroInputs reads = (typeof(TDrag) == typeof(StepanekDragLaw) ? AeroInputs.None : _drag.Reads) | _decay.Reads;
            double spinParameter = (reads & SpinParameterBit) != 0 ? spinRate * (_radius / speed) : 0;
            return new AeroConditions(
                speed, spinRate, 0, _radius, _density, spinParameter, 0,
                (reads & AeroInputs.ReynoldsNumber) != 0 ? _density * speed * 2 * _radius / _viscosity : 0);
        }

        // k2 + k3 is summed as soon as k3 is known (the same sum RungeKutta4 forms, fewer numbers live across the loop).
        private void Rk4Loop<TStages>(in FlightState state, in StateDerivative k1, double step, out FlightState next, out StateDerivative end)
            where TStages : struct, IStageSpinRates
        {
            double half = 0.5 * step;
            double sixth = step / 6.0;
            bool spins = _decay.IsPresent;
            bool positions = _windVaries;
            Vector3d p = state.Position, w = state.AngularVelocity;
            double vx = state.Velocity.X, vy = state.Velocity.Y, vz = state.Velocity.Z;

            // The slope that forms the next stage (velocity, acceleration, spin acceleration), and k2 (then k2 + k3).
            double vkx = vx, vky = vy, vkz = vz, akx = k1.Acceleration.X, aky = k1.Acceleration.Y, akz = k1.Acceleration.Z;
            Vector3d sk = k1.AngularAcceleration;
            double v23x = 0, v23y = 0, v23z = 0, a23x = 0, a23y = 0, a23z = 0;
            Vector3d s23 = default;
            Vector3d ps = p, ws = w;
            double vsx, vsy, vsz;
            double time = state.Time + step;
            SpinRates(w.X, w.Y, w.Z, out double spinRate, out double inverseSpinRate); // the whole step's, when the spin is constant

            // Where the spin decays exponentially (dw/dt = c w, c constant) and Stepanek's lift is folded, the stages' spins
            // are the step's spin times constants of the step (StageSpinFactors): their rates are the step's rate times those,
            // to rounding, instead of three more square roots on the divider the fold's square roots and divisions share
            // (docs/performance.md). The end state's rate is its own (the end rates are the derivative there, bit for bit),
            // formed here with the loop's expressions (the same bits), ahead of the velocity's stages: formed at the end, its
            // square root and the fold's division lay on the chain into the end rates, which the next step starts from.
            // Only for steps of at most one time constant (h |c| <= 1), where every factor is at least 1/4 (g4 falls to 1/4 at
            // h |c| = 1, and g2 to 0 at 2): the rounding of 1 + h c (...) is then amplified at most four-fold, and the rates
            // stay within 2e-15 of the stage spins' own (tested). Longer steps take every stage's own rate, as before. Rk4
            // decides, and passes the answer as TStages.
            bool scaled = default(TStages).Scaled;
            double startRate = spinRate, f2 = 0, f3 = 0, f4 = 0, endRate = 0, endInverse = 0;
            Vector3d endSpin = default;
            if (scaled)
            {
                ScaledStageSpins(w, k1.AngularAcceleration, step, out f2, out f3, out f4, out endSpin, out endRate, out endInverse);
            }

            for (int stage = 0; ; stage++)
            {
                if (stage < 3)
                {
                    // x + c k, FlightState.Advance's expression
                    double c = stage == 2 ? step : half;
                    vsx = vx + c * akx;
                    vsy = vy + c * aky;
                    vsz = vz + c * akz;
                    if (spins)
                    {
                        ws = Add(w, sk, c);
                    }

                    if (positions)
                    {
                        ps = new Vector3d(p.X + c * vkx, p.Y + c * vky, p.Z + c * vkz);
                    }
                }
                else
                {
                    // y + (k1 + 2 (k2 + k3) + k4) h/6, grouped as RungeKutta4 groups it (vk, ak, sk hold k4)
                    Vector3d k1v = k1.Velocity, k1a = k1.Acceleration;
                    ps = new Vector3d(
                        p.X + (k1v.X + v23x * 2.0 + vkx) * sixth,
                        p.Y + (k1v.Y + v23y * 2.0 + vky) * sixth,
                        p.Z + (k1v.Z + v23z * 2.0 + vkz) * sixth);
                    vsx = vx + (k1a.X + a23x * 2.0 + akx) * sixth;
                    vsy = vy + (k1a.Y + a23y * 2.0 + aky) * sixth;
                    vsz = vz + (k1a.Z + a23z * 2.0 + akz) * sixth;
                    ws = spins ? w + (k1.AngularAcceleration + 2.0 * s23 + sk) * sixth : w + k1.AngularAcceleration * sixth;
                }

                if (scaled)
                {
                    if (stage < 3)
                    {
                        spinRate = startRate * (stage == 0 ? f2 : stage == 1 ? f3 : f4);
                    }
                    else
                    {
                        ws = endSpin; // the same expression as the loop's ws above, the same bits, formed before the stages
                        spinRate = endRate;
                        inverseSpinRate = endInverse;
                    }
                }
                else if (spins)
                {
                    SpinRates(ws.X, ws.Y, ws.Z, out spinRate, out inverseSpinRate);
                }

                Rates(ps, vsx, vsy, vsz, ws, spinRate, inverseSpinRate, out Vector3d a, out Vector3d s);
                if (stage == 3)
                {
                    var ve = new Vector3d(vsx, vsy, vsz);
                    next = new FlightState(ps, ve, ws, time);
                    end = new StateDerivative(ve, a, s);
                    return;
                }

                if (stage == 0)
                {
                    v23x = vsx;
                    v23y = vsy;
                    v23z = vsz;
                    a23x = a.X;
                    a23y = a.Y;
                    a23z = a.Z;
                    s23 = s;
                }
                else if (stage == 1)
                {
                    v23x += vsx;
                    v23y += vsy;
                    v23z += vsz;
                    a23x += a.X;
                    a23y += a.Y;
                    a23z += a.Z;
                    s23 += s;
                }

                vkx = vsx;
                vky = vsy;
                vkz = vsz;
                akx = a.X;
                aky = a.Y;
                akz = a.Z;
                sk = s;
            }
        }

        /// <summary>Whether an RK4 step takes its inner stages' spin rates scaled from the step's (Rk4Loop's type argument).</summary>
        private interface IStageSpinRates
        {
            bool Scaled { get; }
        }

        private readonly struct ScaledStageSpinRates : IStageSpinRates
        {
            public bool Scaled => true;
        }

        private readonly struct OwnStageSpinRates : IStageSpinRates
        {
            public bool Scaled => false;
        }

        // One evaluation of an RK4 stage: the spin rates at the stage's spin where the spin changes, then the rates.
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private void Stage(
            in Vector3d position, double vx, double vy, double vz, in Vector3d spin, ref double spinRate, ref double inverseSpinRate,
            out Vector3d acceleration, out Vector3d spinAcceleration)
        {
            if (_decay.IsPresent)
            {
                SpinRates(spin.X, spin.Y, spin.Z, out spinRate, out inverseSpinRate);
            }

            Rates(position, vx, vy, vz, spin, spinRate, inverseSpinRate, out acceleration, out spinAcceleration);
        }

        // x + h k, component by component (FlightState.Advance's expression).
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static Vector3d Add(in Vector3d x, in Vector3d k, double h) => new Vector3d(x.X + h * k.X, x.Y + h * k.Y, x.Z + h * k.Z);
    }

    /// <summary>
    /// Picks the kernel for a model's laws: each built-in law maps to its struct; any other law (a user's own
    /// <see cref="IDragModel"/>, <see cref="ILiftModel"/> or <see cref="ISpinDecayModel"/>) runs through its interface. A
    /// new built-in law needs only its struct in Aerodynamics/CoefficientLaws.cs and one line here; without them it
    /// still works, through the interface.
    /// </summary>
    internal static class FlightKernelFactory
    {
        internal static FlightKernel Create(FlightModel model)
        {
            bool aero = model.Air.Density > 0;
            IDragModel? drag = aero ? model.Drag : null;
            switch (drag)
            {
                case null: return WithDrag(model, default(NoDrag));
                case ConstantDrag c: return WithDrag(model, new ConstantDragLaw(c.Value));
                case StepanekDrag _: return WithDrag(model, default(StepanekDragLaw));
                case LinearSpinDrag l: return WithDrag(model, new LinearSpinDragLaw(l));
                case NathanBaseballDrag _: return WithDrag(model, default(NathanBaseballDragLaw));
                case GoffCarreSoccerDrag _: return WithDrag(model, default(GoffCarreSoccerDragLaw));
                default: return WithDrag(model, new InterfaceDrag(drag));
            }
        }

        private static FlightKernel WithDrag<TDrag>(FlightModel model, TDrag drag)
            where TDrag : struct, IDragLaw
        {
            ILiftModel? lift = model.Air.Density > 0 ? model.Lift : null;
            switch (lift)
            {
                case null: return WithLift(model, drag, default(NoLift));
                case ConstantLift c: return WithLift(model, drag, new ConstantLiftLaw(c.Value));
                case StepanekLift _: return WithLift(model, drag, default(StepanekLiftLaw));
                case LinearSpinLift l: return WithLift(model, drag, new LinearSpinLiftLaw(l.Slope));
                case NathanBaseballLift _: return WithLift(model, drag, default(NathanBaseballLiftLaw));
                case PiecewiseLinearLift t: return WithLift(model, drag, new PiecewiseLinearLiftLaw(t));
                default: return WithLift(model, drag, new InterfaceLift(lift));
            }
        }

        private static FlightKernel WithLift<TDrag, TLift>(FlightModel model, TDrag drag, TLift lift)
            where TDrag : struct, IDragLaw
            where TLift : struct, ILiftLaw
        {
            switch (model.SpinDecay)
            {
                case null: return new FlightKernel<TDrag, TLift, NoSpinDecay>(model, drag, lift, default);
                case ExponentialSpinDecay e:
                    return new FlightKernel<TDrag, TLift, ExponentialSpinDecayLaw>(model, drag, lift, new ExponentialSpinDecayLaw(e.TimeConstant));
                case SpeedProportionalSpinDecay s:
                    return new FlightKernel<TDrag, TLift, SpeedProportionalSpinDecayLaw>(
                        model, drag, lift, new SpeedProportionalSpinDecayLaw(s.RatePerMetre));
                default:
                    return new FlightKernel<TDrag, TLift, InterfaceSpinDecay>(model, drag, lift, new InterfaceSpinDecay(model.SpinDecay));
            }
        }
    }
}
