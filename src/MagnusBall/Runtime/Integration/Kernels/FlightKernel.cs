// FlightKernel: the flight ODE specialised for one model's laws. This file holds the abstract kernel (what the integrators
// call), the generic kernel's fields and its entry points (Derivative, RungeKutta4, RungeKutta4Advance, TryRk4StraightLine,
// Heun, DormandPrince54's declaration), and the factory that picks the kernel. The main path: RungeKutta4 here -> Rk4
// (FlightKernel.Rk4.cs), which picks one of RK4's shapes, each stage's rates from FlightKernel.Rates.cs. The other files:
// FlightKernel.Rates.cs (the rate computations: general, folded, Stepanek's folded lift), FlightKernel.Rk4.cs (RK4's
// unrolled and loop shapes), FlightKernel.Rk4Straight.cs (the straight-line shapes Mono and IL2CPP take),
// FlightKernel.DormandPrince54.cs (the adaptive method's stages).
using System.Runtime.CompilerServices;
using MagnusBall.Aerodynamics;
using MagnusBall.Integration;

namespace MagnusBall.Integration.Kernels
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

        /// <summary>
        /// The kernel of <paramref name="model"/>: built on first use (<see cref="FlightKernelFactory"/>) and kept on the model,
        /// so every later call is a field read. Two threads that build it at once build equal kernels; the first one published
        /// is kept (an interlocked exchange, so no thread sees a kernel before its fields are written).
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static FlightKernel Of(FlightModel model) => model.Specialised as FlightKernel ?? Build(model);

        /// <summary>
        /// The right-hand side through <paramref name="model"/>'s kernel, with the general formula's scaled form where the plain
        /// one overflows (speeds past about 1e150 m/s): what every integrator and flight evaluates, the spec
        /// (<see cref="FlightModel.Derivative"/>) bit for bit except in the kernel's folded forms.
        /// </summary>
        internal static StateDerivative DerivativeOf(FlightModel model, in FlightState state)
        {
            StateDerivative d = Of(model).Derivative(state);
            return d.Acceleration.IsFinite && d.AngularAcceleration.IsFinite ? d : model.ScaledDerivative(state);
        }

        private static FlightKernel Build(FlightModel model)
        {
            FlightKernel kernel = FlightKernelFactory.Create(model);
            kernel.Counter = model.CountedEvaluations;
            object? published = System.Threading.Interlocked.CompareExchange(ref model.Specialised, kernel, null);
            FlightKernel kept = published as FlightKernel ?? kernel;
            kept.Counter = model.CountedEvaluations; // the test hook, whichever kernel won (set before use in every test)
            return kept;
        }

        /// <summary>What a drag or lift law that reads nothing (Reads == None: a constant coefficient) is given.</summary>
        private protected static readonly AeroConditions NoConditions = default;

        /// <summary>
        /// True under Mono and Unity's IL2CPP: take RK4's straight-line forms, for the thesis model's common case (see
        /// Rk4Straight) and for Stepanek's tennis laws folded in still air (Rk4StraightStepanek). RyuJIT keeps the chain in
        /// registers across the branches anyway, and measured the straight-line form 3-5 % slower; it folds this constant
        /// away. Both forms give the same bits.
        /// Compiled by Unity
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
    internal sealed partial class FlightKernel<TDrag, TLift, TDecay> : FlightKernel
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
        }

        private static bool IsPositiveZero(double x) => System.BitConverter.DoubleToInt64Bits(x) == 0;

        /// <summary>The drag, lift and spin-decay laws' type names, for tests and diagnostics.</summary>
        public override string ToString() => $"FlightKernel<{typeof(TDrag).Name}, {typeof(TLift).Name}, {typeof(TDecay).Name}>";

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
            return next;
        }

        internal override bool RunsUserCode =>
            typeof(TDrag) == typeof(InterfaceDrag) || typeof(TLift) == typeof(InterfaceLift) || typeof(TDecay) == typeof(InterfaceSpinDecay);

        internal override void RungeKutta4Into(in FlightState state, in StateDerivative k1, double step, out FlightState next, out StateDerivative end) =>
            Rk4(state, k1, step, out next, out end);

        internal override int RungeKutta4Advance(ref FlightState state, ref StateDerivative derivative, double step, int count)
        {
            // RK4's step repeated in place, stopping before a step whose end would not be finite.
            for (int i = 0; i < count; i++)
            {
                Rk4(state, derivative, step, out FlightState next, out StateDerivative end);
                if (!IsFinite(next, end))
                {
                    return i;
                }

                state = next;
                derivative = end;
            }

            return count;
        }

        // Every component of the state and its derivative finite (the derivative's velocity is the state's).
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static bool IsFinite(in FlightState y, in StateDerivative k) => y.IsFinite && k.Acceleration.IsFinite && k.AngularAcceleration.IsFinite;

        internal override bool TryRk4StraightLine(in FlightState state, in StateDerivative k1, double step, out FlightState end, out StateDerivative endRates)
        {
            if (StepanekStraightCase)
            {
                bool answers = Rk4StraightStepanek(state, k1, step, out end, out Vector3d a, out Vector3d s);
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

        // x + h k, component by component (FlightState.Advance's expression).
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static Vector3d Add(in Vector3d x, in Vector3d k, double h) => new Vector3d(x.X + h * k.X, x.Y + h * k.Y, x.Z + h * k.Z);
    }

    /// <summary>
    /// Builds the kernel for a model's laws: each law's struct comes from the one list of built-in laws
    /// (<see cref="LawCatalogue"/>); a law it does not list (a user's own <see cref="IDragModel"/>, <see cref="ILiftModel"/>
    /// or <see cref="ISpinDecayModel"/>) runs through its interface. A new built-in law needs its struct in
    /// Aerodynamics/CoefficientLaws.cs and its line in the catalogue; nothing here.
    /// </summary>
    internal static class FlightKernelFactory
    {
        internal static FlightKernel Create(FlightModel model)
        {
            bool aero = model.Air.Density > 0;
            var withDrag = new WithDrag(model);
            return LawCatalogue.Drag<WithDrag, FlightKernel>(aero ? model.Drag : null, ref withDrag);
        }

        private readonly struct WithDrag : IDragVisitor<FlightKernel>
        {
            private readonly FlightModel _model;

            internal WithDrag(FlightModel model) => _model = model;

            public FlightKernel Visit<TDrag>(TDrag drag, in LawTraits traits)
                where TDrag : struct, IDragLaw
            {
                var withLift = new WithLift<TDrag>(_model, drag);
                return LawCatalogue.Lift<WithLift<TDrag>, FlightKernel>(_model.Air.Density > 0 ? _model.Lift : null, ref withLift);
            }
        }

        private readonly struct WithLift<TDrag> : ILiftVisitor<FlightKernel>
            where TDrag : struct, IDragLaw
        {
            private readonly FlightModel _model;
            private readonly TDrag _drag;

            internal WithLift(FlightModel model, TDrag drag)
            {
                _model = model;
                _drag = drag;
            }

            public FlightKernel Visit<TLift>(TLift lift, in LawTraits traits)
                where TLift : struct, ILiftLaw
            {
                var withDecay = new WithDecay<TDrag, TLift>(_model, _drag, lift);
                return LawCatalogue.SpinDecay<WithDecay<TDrag, TLift>, FlightKernel>(_model.SpinDecay, ref withDecay);
            }
        }

        private readonly struct WithDecay<TDrag, TLift> : ISpinDecayVisitor<FlightKernel>
            where TDrag : struct, IDragLaw
            where TLift : struct, ILiftLaw
        {
            private readonly FlightModel _model;
            private readonly TDrag _drag;
            private readonly TLift _lift;

            internal WithDecay(FlightModel model, TDrag drag, TLift lift)
            {
                _model = model;
                _drag = drag;
                _lift = lift;
            }

            public FlightKernel Visit<TDecay>(TDecay decay, in LawTraits traits)
                where TDecay : struct, ISpinDecayLaw =>
                new FlightKernel<TDrag, TLift, TDecay>(_model, _drag, _lift, decay);
        }
    }
}
