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

        /// <summary>The right-hand side at <paramref name="state"/> (bit for bit the same as the general formula).</summary>
        internal abstract StateDerivative Derivative(in FlightState state);

        /// <summary>
        /// One classic RK4 step from <paramref name="state"/> with start derivative <paramref name="k1"/>: the state at
        /// state.Time + step and, in <paramref name="end"/>, the derivative there. Four evaluations (k2, k3, k4 and the
        /// end, which is the next step's k1). No argument checks: the caller checks.
        /// </summary>
        internal abstract FlightState RungeKutta4(in FlightState state, in StateDerivative k1, double step, out StateDerivative end);

        /// <summary>
        /// <paramref name="count"/> RK4 steps of <paramref name="step"/> seconds; <paramref name="derivative"/> is the
        /// start derivative on entry and the end derivative on return. 4 x count evaluations. No checks, no events:
        /// a step that overflows carries the non-finite state on (the caller checks the end).
        /// </summary>
        internal abstract FlightState RungeKutta4Steps(in FlightState state, ref StateDerivative derivative, double step, int count);

        /// <summary>One Heun step with its end derivative (2 evaluations). No argument checks.</summary>
        internal abstract FlightState Heun(in FlightState state, in StateDerivative k1, double step, out StateDerivative end);

        /// <summary>
        /// The six stages of one Dormand-Prince 5(4) step from <paramref name="state"/> with start derivative
        /// <paramref name="k1"/> (DormandPrince54's arithmetic term by term): the fifth-order end state and k3..k7 in
        /// <paramref name="stages"/> (k7 is the derivative at the end). Six evaluations. No argument checks. False when a
        /// stage's acceleration or spin acceleration may not be finite (where FlightModel.Derivative would take its scaled
        /// path): the caller then redoes the step through FlightModel.Derivative.
        /// </summary>
        internal abstract bool DormandPrince54(in FlightState state, in StateDerivative k1, double step, out DormandPrince54Stages stages);
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
        }

        /// <summary>The drag, lift and spin-decay laws' type names, for tests and diagnostics.</summary>
        public override string ToString() => $"FlightKernel<{typeof(TDrag).Name}, {typeof(TLift).Name}, {typeof(TDecay).Name}>";

        // The acceleration and spin acceleration at (position, velocity, spin): FlightModel's formula, term by term in the
        // same order (so the bits agree), computing only the inputs some law reads. The Reads/IsPresent checks are
        // constants of the type parameters and fold away.
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private void Rates(
            in Vector3d position, in Vector3d velocity, in Vector3d w, double spinRate, double inverseSpinRate,
            out Vector3d acceleration, out Vector3d spinAcceleration)
        {
            Counter?.Add();
            acceleration = _gravity;
            spinAcceleration = default;
            bool aero = _drag.IsPresent || _lift.IsPresent;
            if (!aero && !_decay.IsPresent)
            {
                return;
            }

            AeroInputs reads = _drag.Reads | _lift.Reads | _decay.Reads;
            bool readsTransverse = (reads & AeroInputs.TransverseSpinRate) != 0;
            bool readsS = (reads & SpinParameterBit) != 0;
            bool readsSPerp = (reads & TransverseSpinParameterBit) != 0;
            bool readsRe = (reads & AeroInputs.ReynoldsNumber) != 0;

            Vector3d relative = velocity - (_windVaries ? _air.WindAt(position, _up) : _wind);
            double speed = relative.Length;
            if (reads == AeroInputs.None)
            {
                // No law reads a spin parameter (the thesis's constant coefficients): the same force with the algebra
                // folded, (rho A / 2m) C_L s^2 (w x v_hat) / |w| = ((rho A / 2m) C_L s / |w|) (w x v_rel), so no 1/s,
                // and 1/|w| once per step where the spin is constant. Equal to the general formula to rounding
                // (FlightKernelTests: within 4 ulp of the largest term), not bit for bit.
                if (speed > FlightModel.MinimumAerodynamicSpeed)
                {
                    var plain = new AeroConditions(speed, spinRate, 0, _radius, _density, 0, 0, 0);
                    if (_drag.IsPresent)
                    {
                        double dragScale = -_factor * _drag.Coefficient(plain) * speed;
                        acceleration += relative * dragScale;
                    }

                    if (_lift.IsPresent && spinRate > 0)
                    {
                        double liftScale = _factor * _lift.Coefficient(plain) * speed * inverseSpinRate;
                        acceleration += Vector3d.Cross(w, relative) * liftScale;
                    }

                    if (_decay.IsPresent)
                    {
                        spinAcceleration = _decay.SpinAcceleration(w, plain);
                    }
                }
                else if (_decay.IsPresent)
                {
                    spinAcceleration = _decay.SpinAcceleration(w, new AeroConditions(0, spinRate, 0, _radius, _density, 0, 0, 0));
                }

                return;
            }

            if (speed > FlightModel.MinimumAerodynamicSpeed)
            {
                Vector3d spinCross = default;
                double transverse = 0;
                if (_lift.IsPresent || readsTransverse)
                {
                    Vector3d direction = relative / speed;
                    spinCross = Vector3d.Cross(w, direction);
                    if (readsTransverse)
                    {
                        transverse = spinCross.Length;
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
                    acceleration += relative * dragScale;
                }

                if (_lift.IsPresent && spinRate > 0)
                {
                    // F_M / m = (rho A / 2m) C_L s^2 (w x v_hat) / |w|  (transverse-spin form)
                    double liftScale = _factor * _lift.Coefficient(conditions) * speed * speed / spinRate;
                    acceleration += spinCross * liftScale;
                }

                if (_decay.IsPresent)
                {
                    spinAcceleration = _decay.SpinAcceleration(w, conditions);
                }
            }
            else if (_decay.IsPresent)
            {
                var still = new AeroConditions(0, spinRate, 0, _radius, _density, 0, 0, 0);
                spinAcceleration = _decay.SpinAcceleration(w, still);
            }
        }

        // |w| where some law reads it or lift needs it (else 0), and 1/|w| where the folded lift uses it (else 0).
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private void SpinRates(in Vector3d w, out double spinRate, out double inverseSpinRate)
        {
            AeroInputs reads = _drag.Reads | _lift.Reads | _decay.Reads;
            spinRate = _lift.IsPresent || (reads & AeroInputs.SpinRate) != 0 ? w.Length : 0;
            inverseSpinRate = reads == AeroInputs.None && _lift.IsPresent && spinRate > 0 ? 1.0 / spinRate : 0;
        }

        internal override StateDerivative Derivative(in FlightState state)
        {
            SpinRates(state.AngularVelocity, out double spinRate, out double inverseSpinRate);
            Rates(state.Position, state.Velocity, state.AngularVelocity, spinRate, inverseSpinRate, out Vector3d acceleration, out Vector3d spinAcceleration);
            return new StateDerivative(state.Velocity, acceleration, spinAcceleration);
        }

        internal override FlightState RungeKutta4(in FlightState state, in StateDerivative k1, double step, out StateDerivative end)
        {
            FlightState next = Rk4(state, k1, step, out Vector3d acceleration, out Vector3d spinAcceleration);
            end = new StateDerivative(next.Velocity, acceleration, spinAcceleration);
            return next;
        }

        internal override FlightState RungeKutta4Steps(in FlightState state, ref StateDerivative derivative, double step, int count)
        {
            FlightState current = state;
            StateDerivative k = derivative;
            for (int i = 0; i < count; i++)
            {
                current = Rk4(current, k, step, out Vector3d acceleration, out Vector3d spinAcceleration);
                k = new StateDerivative(current.Velocity, acceleration, spinAcceleration);
            }

            derivative = k;
            return current;
        }

        internal override FlightState Heun(in FlightState state, in StateDerivative k1, double step, out StateDerivative end)
        {
            // Heun.Step's arithmetic: k2 at state.Advance(k1, step), then the average of the slopes.
            Vector3d p = state.Position, v = state.Velocity, w = state.AngularVelocity;
            Vector3d v2 = Add(v, k1.Acceleration, step);
            Vector3d w2 = _decay.IsPresent ? Add(w, k1.AngularAcceleration, step) : w;
            Vector3d p2 = _windVaries ? Add(p, k1.Velocity, step) : p;
            SpinRates(w2, out double spin2, out double inverse2);
            Rates(p2, v2, w2, spin2, inverse2, out Vector3d a2, out Vector3d wd2);
            double half = 0.5 * step;
            var next = new FlightState(
                p + (k1.Velocity + v2) * half,
                v + (k1.Acceleration + a2) * half,
                w + (k1.AngularAcceleration + wd2) * half,
                state.Time + step);
            SpinRates(next.AngularVelocity, out double spin, out double inverse);
            Rates(next.Position, next.Velocity, next.AngularVelocity, spin, inverse, out Vector3d a, out Vector3d wd);
            end = new StateDerivative(next.Velocity, a, wd);
            return next;
        }

        internal override bool DormandPrince54(in FlightState state, in StateDerivative k1, double step, out DormandPrince54Stages stages)
        {
            // DormandPrince54's arithmetic term by term (Dp54Stage forms each stage, Dp54Rates holds k1..k6). One evaluation
            // site (a loop over k2..k7), so the inlined laws appear once in the code; the stage positions are formed only
            // where the wind depends on the height, the stage spins only where the spin decays (otherwise every stage spin
            // is the start spin plus zero rates); the end state is formed in full.
            Dp54Rates k = default;
            k.V1 = k1.Velocity;
            k.A1 = k1.Acceleration;
            k.S1 = k1.AngularAcceleration;
            double h = step;
            double check = 0; // the sum of every stage's rates: finite when each of them is (or spuriously not, on overflow)
            SpinRates(state.AngularVelocity, out double spinRate, out double inverseSpinRate); // the whole step's, when the spin is constant
            for (int stage = 1; ; stage++)
            {
                // stage 1..5: k2..k6; stage 6: the end, where k7 is evaluated
                Dp54Stage(ref k, stage, h, state, out Vector3d ps, out Vector3d vs, out Vector3d ws);
                bool end = stage == 6;
                if (_decay.IsPresent || end)
                {
                    SpinRates(ws, out spinRate, out inverseSpinRate);
                }

                Rates(ps, vs, ws, spinRate, inverseSpinRate, out Vector3d a, out Vector3d s);
                check += a.X + a.Y + a.Z + s.X + s.Y + s.Z;
                switch (stage)
                {
                    case 1:
                        k.V2 = vs;
                        k.A2 = a;
                        k.S2 = s;
                        break;
                    case 2:
                        k.V3 = vs;
                        k.A3 = a;
                        k.S3 = s;
                        break;
                    case 3:
                        k.V4 = vs;
                        k.A4 = a;
                        k.S4 = s;
                        break;
                    case 4:
                        k.V5 = vs;
                        k.A5 = a;
                        k.S5 = s;
                        break;
                    case 5:
                        k.V6 = vs;
                        k.A6 = a;
                        k.S6 = s;
                        break;
                    default:
                        // Written field by field, in place (the caller's stages are part of its step; the inputs are read by now).
                        stages.End = new FlightState(ps, vs, ws, state.Time + h);
                        stages.K3 = new StateDerivative(k.V3, k.A3, k.S3);
                        stages.K4 = new StateDerivative(k.V4, k.A4, k.S4);
                        stages.K5 = new StateDerivative(k.V5, k.A5, k.S5);
                        stages.K6 = new StateDerivative(k.V6, k.A6, k.S6);
                        stages.K7 = new StateDerivative(vs, a, s);
                        return double.IsFinite(check);
                }
            }
        }

        // Stage `stage` of Dormand-Prince 5(4) (1..5: the states of k2..k6; 6: the fifth-order end): y + (h a_i1) k1 +
        // (h a_i2) k2 + ..., left to right as DormandPrince54's Combine sums it (stage 1 as FlightState.Advance(k1, a21 h));
        // the end leaves k2 out (b2 = 0), as there. Not inlined: one small copy serves the loop above.
        [MethodImpl(MethodImplOptions.NoInlining)]
        private void Dp54Stage(ref Dp54Rates k, int stage, double h, in FlightState y, out Vector3d ps, out Vector3d vs, out Vector3d ws)
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
                    vs = Add(v, k.A1, c);
                    if (spins)
                    {
                        ws = Add(w, k.S1, c);
                    }

                    if (positions)
                    {
                        ps = Add(p, k.V1, c);
                    }

                    return;
                }

                case 2:
                {
                    double ha = h * DP.A31, hb = h * DP.A32;
                    vs = Add(Add(v, k.A1, ha), k.A2, hb);
                    if (spins)
                    {
                        ws = Add(Add(w, k.S1, ha), k.S2, hb);
                    }

                    if (positions)
                    {
                        ps = Add(Add(p, k.V1, ha), k.V2, hb);
                    }

                    return;
                }

                case 3:
                {
                    double ha = h * DP.A41, hb = h * DP.A42, hc = h * DP.A43;
                    vs = Add(Add(Add(v, k.A1, ha), k.A2, hb), k.A3, hc);
                    if (spins)
                    {
                        ws = Add(Add(Add(w, k.S1, ha), k.S2, hb), k.S3, hc);
                    }

                    if (positions)
                    {
                        ps = Add(Add(Add(p, k.V1, ha), k.V2, hb), k.V3, hc);
                    }

                    return;
                }

                case 4:
                {
                    double ha = h * DP.A51, hb = h * DP.A52, hc = h * DP.A53, hd = h * DP.A54;
                    vs = Add(Add(Add(Add(v, k.A1, ha), k.A2, hb), k.A3, hc), k.A4, hd);
                    if (spins)
                    {
                        ws = Add(Add(Add(Add(w, k.S1, ha), k.S2, hb), k.S3, hc), k.S4, hd);
                    }

                    if (positions)
                    {
                        ps = Add(Add(Add(Add(p, k.V1, ha), k.V2, hb), k.V3, hc), k.V4, hd);
                    }

                    return;
                }

                case 5:
                {
                    double ha = h * DP.A61, hb = h * DP.A62, hc = h * DP.A63, hd = h * DP.A64, he = h * DP.A65;
                    vs = Add(Add(Add(Add(Add(v, k.A1, ha), k.A2, hb), k.A3, hc), k.A4, hd), k.A5, he);
                    if (spins)
                    {
                        ws = Add(Add(Add(Add(Add(w, k.S1, ha), k.S2, hb), k.S3, hc), k.S4, hd), k.S5, he);
                    }

                    if (positions)
                    {
                        ps = Add(Add(Add(Add(Add(p, k.V1, ha), k.V2, hb), k.V3, hc), k.V4, hd), k.V5, he);
                    }

                    return;
                }

                default:
                {
                    double ha = h * DP.B1, hc = h * DP.B3, hd = h * DP.B4, he = h * DP.B5, hf = h * DP.B6;
                    vs = Add(Add(Add(Add(Add(v, k.A1, ha), k.A3, hc), k.A4, hd), k.A5, he), k.A6, hf);
                    ws = Add(Add(Add(Add(Add(w, k.S1, ha), k.S3, hc), k.S4, hd), k.S5, he), k.S6, hf);
                    ps = Add(Add(Add(Add(Add(p, k.V1, ha), k.V3, hc), k.V4, hd), k.V5, he), k.V6, hf);
                    return;
                }
            }
        }

        // k1..k6 of a Dormand-Prince step: each stage's velocity (the position rate), acceleration and spin acceleration.
        private struct Dp54Rates
        {
            public Vector3d V1, V2, V3, V4, V5, V6;
            public Vector3d A1, A2, A3, A4, A5, A6;
            public Vector3d S1, S2, S3, S4, S5, S6;
        }

        // One RK4 step, RungeKutta4.Step's arithmetic term by term, plus the end rates. One evaluation site (a loop over
        // the four evaluations k2, k3, k4 and the end), so the inlined laws appear once in the code and their numbers
        // stay in registers (four inlined copies made a 6 kB method with a 1.6 kB stack frame). The stage positions are
        // formed only when the wind depends on the height (no law reads the position otherwise), the stage spins only
        // when the spin decays (otherwise its rate is zero and every stage spin equals the start spin).
        private FlightState Rk4(in FlightState state, in StateDerivative k1, double step, out Vector3d endAcceleration, out Vector3d endSpinAcceleration)
        {
            double half = 0.5 * step;
            double sixth = step / 6.0;
            Vector3d p = state.Position, v = state.Velocity, w = state.AngularVelocity;
            bool spins = _decay.IsPresent;
            bool positions = _windVaries;

            Vector3d v2 = default, v3 = default, a2 = default, a3 = default, s2 = default, s3 = default;
            Vector3d vk = v, ak = k1.Acceleration, sk = k1.AngularAcceleration; // the slope that forms the next stage
            Vector3d ps = p, vs, ws = w;
            SpinRates(w, out double spinRate, out double inverseSpinRate); // the whole step's, when the spin is constant
            for (int stage = 0; ; stage++)
            {
                if (stage < 3)
                {
                    double c = stage == 2 ? step : half;
                    vs = Add(v, ak, c);
                    if (spins)
                    {
                        ws = Add(w, sk, c);
                    }

                    if (positions)
                    {
                        ps = Add(p, vk, c);
                    }
                }
                else
                {
                    // y + (k1 + 2 (k2 + k3) + k4) h/6, grouped as RungeKutta4 groups it (vk, ak, sk hold k4)
                    ps = p + (k1.Velocity + 2.0 * (v2 + v3) + vk) * sixth;
                    vs = v + (k1.Acceleration + 2.0 * (a2 + a3) + ak) * sixth;
                    ws = spins ? w + (k1.AngularAcceleration + 2.0 * (s2 + s3) + sk) * sixth : w + k1.AngularAcceleration * sixth;
                }

                if (spins)
                {
                    SpinRates(ws, out spinRate, out inverseSpinRate);
                }

                Rates(ps, vs, ws, spinRate, inverseSpinRate, out Vector3d a, out Vector3d s);
                if (stage == 3)
                {
                    endAcceleration = a;
                    endSpinAcceleration = s;
                    return new FlightState(ps, vs, ws, state.Time + step);
                }

                if (stage == 0)
                {
                    v2 = vs;
                    a2 = a;
                    s2 = s;
                }
                else if (stage == 1)
                {
                    v3 = vs;
                    a3 = a;
                    s3 = s;
                }

                vk = vs;
                ak = a;
                sk = s;
            }
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
