using System.Numerics;
using System.Runtime.CompilerServices;
using MagnusBall.Aerodynamics;

namespace MagnusBall.Batch
{
    /// <summary>
    /// A model's coefficient laws in vector form, for <see cref="BallBatch"/>: each lane computes exactly what
    /// <see cref="FlightKernel{TDrag, TLift, TDecay}"/> computes for one ball (same operations, same order), so the batch
    /// equals the single-ball path bit for bit. The law kinds are read once per call (a predictable branch).
    /// </summary>
    internal readonly struct VectorLaws
    {
        internal enum DragKind
        {
            None,
            Constant,
            Stepanek,
        }

        internal enum LiftKind
        {
            None,
            Constant,
            LinearSpin,
            Stepanek,
        }

        internal enum DecayKind
        {
            None,
            Exponential,
        }

        internal readonly bool Supported;
        internal readonly DragKind Drag;
        internal readonly LiftKind Lift;
        internal readonly DecayKind Decay;
        private readonly double _dragConstant;  // -k C_D (constant drag)
        private readonly double _negativeFactor; // -k
        private readonly double _factor;         // k
        private readonly double _liftConstant;  // k C_L (constant lift) or the slope (linear lift)
        private readonly double _decayFactor;   // -1 / tau
        private readonly double _radius;
        private readonly Vector3d _gravity;
        private readonly Vector3d _wind;
        private readonly bool _foldsLift; // the kernel folds Stepanek's lift for this model (k and r in range)

        private VectorLaws(
            bool supported, DragKind drag, LiftKind lift, DecayKind decay, double dragValue, double liftValue, double decayFactor, FlightModel model)
        {
            Supported = supported;
            Drag = drag;
            Lift = lift;
            Decay = decay;
            _factor = model.AerodynamicFactor;
            _negativeFactor = -_factor;
            _dragConstant = -_factor * dragValue;
            _liftConstant = lift == LiftKind.Constant ? _factor * liftValue : liftValue;
            _decayFactor = decayFactor;
            _radius = model.Ball.Radius;
            _gravity = model.Gravity;
            _wind = model.Air.Wind;
            _foldsLift = FlightKernel.FoldsLiftAtScale(_factor, _radius);
        }

        internal static VectorLaws For(FlightModel model)
        {
            bool aero = model.Air.Density > 0;
            bool supported = !(model.Air.WindProfile != null && model.Up.LengthSquared > 0);
            DragKind drag = DragKind.None;
            double dragValue = 0;
            switch (aero ? model.Drag : null)
            {
                case null:
                    break;
                case ConstantDrag c:
                    drag = DragKind.Constant;
                    dragValue = c.Value;
                    break;
                case StepanekDrag _:
                    // StepanekDrag.FromConditions takes 1/S as 1/S itself where r |w| is not a normal double. The lanes never
                    // need that (their |w| is at most about 1.3e154 rad/s and their speed above 1e-150 m/s, so an underflowing
                    // r |w| gives u^2.5 = +inf either way) unless the radius passes about 1e154 m: such a ball goes ball by ball.
                    supported &= model.Ball.Radius <= 1e150;
                    drag = DragKind.Stepanek;
                    break;
                default:
                    supported = false;
                    break;
            }

            LiftKind lift = LiftKind.None;
            double liftValue = 0;
            switch (aero ? model.Lift : null)
            {
                case null:
                    break;
                case ConstantLift c:
                    lift = LiftKind.Constant;
                    liftValue = c.Value;
                    break;
                case LinearSpinLift l:
                    lift = LiftKind.LinearSpin;
                    liftValue = l.Slope;
                    break;
                case StepanekLift _:
                    lift = LiftKind.Stepanek;
                    break;
                default:
                    supported = false;
                    break;
            }

            DecayKind decay = DecayKind.None;
            double decayFactor = 0;
            switch (model.SpinDecay)
            {
                case null:
                    break;
                case ExponentialSpinDecay e:
                    decay = DecayKind.Exponential;
                    decayFactor = -1.0 / e.TimeConstant;
                    break;
                default:
                    supported = false;
                    break;
            }

            return new VectorLaws(supported, drag, lift, decay, dragValue, liftValue, decayFactor, model);
        }

        /// <summary>
        /// The acceleration and spin acceleration at velocity v and spin w, lane by lane (the kernel's Rates).
        /// <paramref name="unfolded"/> marks the lanes where the kernel would take the general formula for Stepanek's
        /// lift instead of its folded form (values out of the fold's range): their numbers here are not the kernel's,
        /// and the caller steps those balls one by one.
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal void Rates(
            Vector<double> vx, Vector<double> vy, Vector<double> vz, Vector<double> wx, Vector<double> wy, Vector<double> wz,
            out Vector<double> ax, out Vector<double> ay, out Vector<double> az,
            out Vector<double> sx, out Vector<double> sy, out Vector<double> sz, out Vector<long> unfolded)
        {
            unfolded = Vector<long>.Zero;
            var gx = new Vector<double>(_gravity.X);
            var gy = new Vector<double>(_gravity.Y);
            var gz = new Vector<double>(_gravity.Z);
            ax = gx;
            ay = gy;
            az = gz;
            if (Decay == DecayKind.Exponential)
            {
                var c = new Vector<double>(_decayFactor);
                sx = wx * c;
                sy = wy * c;
                sz = wz * c;
            }
            else
            {
                sx = Vector<double>.Zero;
                sy = Vector<double>.Zero;
                sz = Vector<double>.Zero;
            }

            if (Drag == DragKind.None && Lift == LiftKind.None)
            {
                return;
            }

            Vector<double> rx = vx - new Vector<double>(_wind.X), ry = vy - new Vector<double>(_wind.Y), rz = vz - new Vector<double>(_wind.Z);
            Vector<double> speed = Vector.SquareRoot(rx * rx + ry * ry + rz * rz);
            Vector<long> aero = Vector.GreaterThan(speed, new Vector<double>(FlightModel.MinimumAerodynamicSpeed));
            bool needsSpinRate = Lift != LiftKind.None || Drag == DragKind.Stepanek;
            Vector<double> spinRate = needsSpinRate ? Vector.SquareRoot(wx * wx + wy * wy + wz * wz) : Vector<double>.Zero;
            bool needsRadiusOverSpeed = Drag == DragKind.Stepanek || Lift == LiftKind.LinearSpin || (Lift == LiftKind.Stepanek && !_foldsLift);
            Vector<double> inverse = needsRadiusOverSpeed ? new Vector<double>(_radius) / speed : Vector<double>.Zero;

            if (Lift == LiftKind.Constant && Drag != DragKind.Stepanek)
            {
                // No law reads a spin parameter: the kernel's folded form. Where the lift acts,
                // g + s ((-k C_D) v_rel + (k C_L / |w|) (w x v_rel)); elsewhere the drag alone, g + v_rel ((-k C_D) s).
                Vector<double> liftScale = new Vector<double>(_liftConstant) * (Vector<double>.One / spinRate);
                Vector<long> lifts = aero & Vector.GreaterThan(spinRate, new Vector<double>(FlightModel.MinimumLiftSpinRate));
                Vector<double> ux = (wy * rz - wz * ry) * liftScale, uy = (wz * rx - wx * rz) * liftScale, uz = (wx * ry - wy * rx) * liftScale;
                if (Drag == DragKind.Constant)
                {
                    var dragFactor = new Vector<double>(_dragConstant);
                    ux = rx * dragFactor + ux;
                    uy = ry * dragFactor + uy;
                    uz = rz * dragFactor + uz;
                    Vector<double> dragScale = dragFactor * speed;
                    ax = Vector.ConditionalSelect(aero, gx + rx * dragScale, gx);
                    ay = Vector.ConditionalSelect(aero, gy + ry * dragScale, gy);
                    az = Vector.ConditionalSelect(aero, gz + rz * dragScale, gz);
                }

                ax = Vector.ConditionalSelect(lifts, gx + speed * ux, ax);
                ay = Vector.ConditionalSelect(lifts, gy + speed * uy, ay);
                az = Vector.ConditionalSelect(lifts, gz + speed * uz, az);
                return;
            }

            if (Lift == LiftKind.Stepanek && _foldsLift)
            {
                // The kernel's folded Stepanek lift and drag (FlightKernel's TryFoldedRates), the same operations. Lanes outside
                // the range the kernel folds in (where it takes the general formula) are marked for the per-ball step.
                Vector<double> qx = wy * rz - wz * ry, qy = wz * rx - wx * rz, qz = wx * ry - wy * rx;
                Vector<double> squared = rx * rx + ry * ry + rz * rz;
                Vector<double> transverseSquared = qx * qx + qy * qy + qz * qz;
                Vector<double> rt = new Vector<double>(_radius) * Vector.SquareRoot(transverseSquared);
                Vector<double> cl = rt / (new Vector<double>(2.022) * rt + new Vector<double>(0.981) * squared);
                Vector<double> liftScale = new Vector<double>(_factor) / spinRate * speed * cl;
                Vector<long> lifts = aero & Vector.GreaterThan(spinRate, new Vector<double>(FlightModel.MinimumLiftSpinRate));
                var low = new Vector<double>(FlightKernel.FoldMinimumSquare);
                var high = new Vector<double>(FlightKernel.FoldMaximumSquare);
                Vector<long> inRange = Vector.GreaterThanOrEqual(spinRate, new Vector<double>(FlightKernel.FoldMinimum)) &
                    Vector.LessThanOrEqual(spinRate, new Vector<double>(FlightKernel.FoldMaximum)) &
                    Vector.GreaterThanOrEqual(squared, low) & Vector.LessThanOrEqual(squared, high) &
                    (Vector.Equals(transverseSquared, Vector<double>.Zero) |
                        (Vector.GreaterThanOrEqual(transverseSquared, low) & Vector.LessThanOrEqual(transverseSquared, high)));
                unfolded = lifts & ~inRange;
                Vector<double> fx = gx + qx * liftScale, fy = gy + qy * liftScale, fz = gz + qz * liftScale;
                if (Drag == DragKind.Stepanek)
                {
                    Vector<double> spinPart = StepanekSpinPart(spinRate * inverse, speed, spinRate);
                    Vector<double> scale = new Vector<double>(_negativeFactor) * speed;
                    Vector<double> ex = rx * scale, ey = ry * scale, ez = rz * scale;
                    var constant = new Vector<double>(0.508);
                    fx = (fx + ex * constant) + spinPart * ex;
                    fy = (fy + ey * constant) + spinPart * ey;
                    fz = (fz + ez * constant) + spinPart * ez;
                    // Lanes that fly without lift (|w| at or below FlightModel.MinimumLiftSpinRate): the general drag.
                    Vector<double> dragScale = new Vector<double>(_negativeFactor) * (constant + spinPart) * speed;
                    ax = Vector.ConditionalSelect(aero, gx + rx * dragScale, gx);
                    ay = Vector.ConditionalSelect(aero, gy + ry * dragScale, gy);
                    az = Vector.ConditionalSelect(aero, gz + rz * dragScale, gz);
                }
                else if (Drag == DragKind.Constant)
                {
                    Vector<double> dragScale = new Vector<double>(_dragConstant) * speed;
                    ax = Vector.ConditionalSelect(aero, gx + rx * dragScale, gx);
                    ay = Vector.ConditionalSelect(aero, gy + ry * dragScale, gy);
                    az = Vector.ConditionalSelect(aero, gz + rz * dragScale, gz);
                    fx = ax + qx * liftScale;
                    fy = ay + qy * liftScale;
                    fz = az + qz * liftScale;
                }

                ax = Vector.ConditionalSelect(lifts, fx, ax);
                ay = Vector.ConditionalSelect(lifts, fy, ay);
                az = Vector.ConditionalSelect(lifts, fz, az);
                return;
            }

            if (Drag != DragKind.None)
            {
                Vector<double> dragScale;
                if (Drag == DragKind.Constant)
                {
                    dragScale = new Vector<double>(_dragConstant) * speed;
                }
                else
                {
                    Vector<double> cd = StepanekDrag(spinRate * inverse, speed, spinRate);
                    dragScale = new Vector<double>(_negativeFactor) * cd * speed;
                }

                ax = Vector.ConditionalSelect(aero, gx + rx * dragScale, gx);
                ay = Vector.ConditionalSelect(aero, gy + ry * dragScale, gy);
                az = Vector.ConditionalSelect(aero, gz + rz * dragScale, gz);
            }

            if (Lift != LiftKind.None)
            {
                Vector<double> unit = Vector<double>.One / speed;
                Vector<double> dx = rx * unit, dy = ry * unit, dz = rz * unit;
                Vector<double> cx = wy * dz - wz * dy, cy = wz * dx - wx * dz, cz = wx * dy - wy * dx;
                Vector<double> liftTimesFactor;
                if (Lift == LiftKind.Constant)
                {
                    liftTimesFactor = new Vector<double>(_liftConstant);
                }
                else
                {
                    Vector<double> transverse = Vector.SquareRoot(cx * cx + cy * cy + cz * cz);
                    Vector<double> sPerp = transverse * inverse;
                    Vector<double> cl = Lift == LiftKind.LinearSpin ? new Vector<double>(_liftConstant) * sPerp : StepanekLift(sPerp);
                    liftTimesFactor = new Vector<double>(_factor) * cl;
                }

                Vector<double> liftScale = liftTimesFactor * speed * speed / spinRate;
                Vector<long> lifts = aero & Vector.GreaterThan(spinRate, new Vector<double>(FlightModel.MinimumLiftSpinRate));
                ax = Vector.ConditionalSelect(lifts, ax + cx * liftScale, ax);
                ay = Vector.ConditionalSelect(lifts, ay + cy * liftScale, ay);
                az = Vector.ConditionalSelect(lifts, az + cz * liftScale, az);
            }
        }

        // Aerodynamics.StepanekDrag.FromConditions, lane by lane: spin parameter s, speed and spin rate.
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private Vector<double> StepanekDrag(Vector<double> s, Vector<double> speed, Vector<double> spinRate) =>
            new Vector<double>(0.508) + StepanekSpinPart(s, speed, spinRate);

        // Aerodynamics.StepanekDrag.SpinPart, lane by lane (0 where S <= 0).
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private Vector<double> StepanekSpinPart(Vector<double> s, Vector<double> speed, Vector<double> spinRate)
        {
            Vector<long> positive = Vector.GreaterThan(s, Vector<double>.Zero);
            Vector<double> u = speed * (Vector<double>.One / (new Vector<double>(_radius) * spinRate));
            Vector<double> x = new Vector<double>(22.053) + new Vector<double>(4.196) * (u * u) * Vector.SquareRoot(u);
            return Vector.ConditionalSelect(positive, PowMinusTwoFifths(x), Vector<double>.Zero);
        }

        // Aerodynamics.StepanekLift.Evaluate, lane by lane.
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static Vector<double> StepanekLift(Vector<double> s)
        {
            Vector<long> positive = Vector.GreaterThan(s, Vector<double>.Zero);
            return Vector.ConditionalSelect(positive, s / (new Vector<double>(2.022) * s + new Vector<double>(0.981)), Vector<double>.Zero);
        }

        /// <summary>
        /// <see cref="Aerodynamics.StepanekDrag.PowMinusTwoFifths"/> lane by lane, the same operations (lanes below 1 or
        /// NaN give garbage the caller discards).
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static Vector<double> PowMinusTwoFifths(Vector<double> x)
        {
            Vector<long> bits = Vector.AsVectorInt64(x);
            // The exponent field as a double: (E 2^52) converts exactly (at most 11 significant bits), then times 2^-52.
            Vector<double> biased = Vector.ConvertToDouble(bits & new Vector<long>(0x7FF0_0000_0000_0000L)) * new Vector<double>(1.0 / 4503599627370496.0);
            Vector<double> e = biased - new Vector<double>(1023);
            Vector<double> m = Vector.AsVectorDouble((bits & new Vector<long>(0x000F_FFFF_FFFF_FFFFL)) | new Vector<long>(0x3FF0_0000_0000_0000L));
            // q = floor(e / 5) (e >= 0): (e + 0.5) / 5 - 0.5 lies within 0.4 of q, and adding and subtracting 2^52 rounds it
            // to the nearest integer (exact: every value here is a small integer or within 2^52).
            Vector<double> q = (((e + new Vector<double>(0.5)) * new Vector<double>(0.2) - new Vector<double>(0.5)) + new Vector<double>(Magic)) -
                new Vector<double>(Magic);
            Vector<double> r = e - new Vector<double>(5) * q;
            Vector<double> t = m - new Vector<double>(1.5);
            Vector<double> t2 = t * t, t4 = t2 * t2, t8 = t4 * t4, t16 = t8 * t8;
            Vector<double> q0 = Pair(t, Aerodynamics.StepanekDrag.D0, Aerodynamics.StepanekDrag.D1) + t2 * Pair(t, Aerodynamics.StepanekDrag.D2, Aerodynamics.StepanekDrag.D3);
            Vector<double> q1 = Pair(t, Aerodynamics.StepanekDrag.D4, Aerodynamics.StepanekDrag.D5) + t2 * Pair(t, Aerodynamics.StepanekDrag.D6, Aerodynamics.StepanekDrag.D7);
            Vector<double> q2 = Pair(t, Aerodynamics.StepanekDrag.D8, Aerodynamics.StepanekDrag.D9) + t2 * Pair(t, Aerodynamics.StepanekDrag.D10, Aerodynamics.StepanekDrag.D11);
            Vector<double> q3 = Pair(t, Aerodynamics.StepanekDrag.D12, Aerodynamics.StepanekDrag.D13) + t2 * Pair(t, Aerodynamics.StepanekDrag.D14, Aerodynamics.StepanekDrag.D15);
            Vector<double> q4 = Pair(t, Aerodynamics.StepanekDrag.D16, Aerodynamics.StepanekDrag.D17) + t2 * Pair(t, Aerodynamics.StepanekDrag.D18, Aerodynamics.StepanekDrag.D19);
            Vector<double> q5 = Pair(t, Aerodynamics.StepanekDrag.D20, Aerodynamics.StepanekDrag.D21) + t2 * new Vector<double>(Aerodynamics.StepanekDrag.D22);
            Vector<double> rest = ((q0 + t4 * q1) + t8 * (q2 + t4 * q3)) + t16 * (q4 + t4 * q5);
            Vector<double> p = new Vector<double>(Aerodynamics.StepanekDrag.C0) + t * rest;
            // 2^(-2r/5) for r = 0..4 by selection (the scalar code reads the same constants from a table).
            Vector<double> table = Vector<double>.One;
            Select(r, 1, Aerodynamics.StepanekDrag.TwoToMinusTwoFifths1, ref table);
            Select(r, 2, Aerodynamics.StepanekDrag.TwoToMinusTwoFifths2, ref table);
            Select(r, 3, Aerodynamics.StepanekDrag.TwoToMinusTwoFifths3, ref table);
            Select(r, 4, Aerodynamics.StepanekDrag.TwoToMinusTwoFifths4, ref table);
            // 2^(-2q): its bit pattern (1023 - 2q) 2^52. 1023 - 2q + 2^52 holds the integer in its low bits; subtracting
            // 2^52's bits gives it as a long, and times 2^52 moves it into the exponent field (no conversion instruction,
            // which Vector<T> lacks on some runtimes).
            Vector<long> biasedScale = Vector.AsVectorInt64(new Vector<double>(1023) - new Vector<double>(2) * q + new Vector<double>(Magic)) -
                new Vector<long>(MagicBits);
            Vector<double> scale = Vector.AsVectorDouble(biasedScale * new Vector<long>(1L << 52));
            Vector<long> finite = Vector.LessThanOrEqual(x, new Vector<double>(double.MaxValue));
            return Vector.ConditionalSelect(finite, p * (table * scale), Vector<double>.Zero); // the scalar code's grouping
        }

        private const double Magic = 4503599627370496.0; // 2^52
        private const long MagicBits = 0x4330_0000_0000_0000L; // its bit pattern

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static void Select(Vector<double> r, double value, double tableValue, ref Vector<double> table) =>
            table = Vector.ConditionalSelect(Vector.Equals(r, new Vector<double>(value)), new Vector<double>(tableValue), table);

        // c0 + t c1, the Estrin scheme's first level (Aerodynamics.StepanekDrag.Rest).
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static Vector<double> Pair(Vector<double> t, double c0, double c1) => new Vector<double>(c0) + t * new Vector<double>(c1);
    }
}
