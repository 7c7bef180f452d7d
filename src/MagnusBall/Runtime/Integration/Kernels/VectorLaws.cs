using System.Numerics;
using System.Runtime.CompilerServices;
using MagnusBall.Aerodynamics;

using MagnusBall.Integration.Kernels;

namespace MagnusBall.Batch
{
    /// <summary>
    /// A model's coefficient laws in vector form, for <see cref="BallBatch"/>: each lane computes exactly what
    /// <see cref="FlightKernel{TDrag, TLift, TDecay}"/> computes for one ball (same operations, same order), so the batch
    /// equals the single-ball path bit for bit. The law kinds are read once per call (a predictable branch).
    /// </summary>
    internal readonly struct VectorLaws
    {
        internal readonly bool Supported;
        internal readonly LaneForm Drag;  // Off, Constant or Stepanek where Supported
        internal readonly LaneForm Lift;  // Off, Constant, LinearSpin or Stepanek where Supported
        internal readonly LaneForm Decay; // Off or Exponential where Supported
        private readonly double _dragConstant;  // -k C_D (constant drag)
        private readonly double _negativeFactor; // -k
        private readonly double _factor;         // k
        private readonly double _liftConstant;  // k C_L (constant lift) or the slope (linear lift)
        private readonly double _decayFactor;   // -1 / tau
        private readonly double _radius;
        private readonly Vector3d _gravity;
        private readonly Vector3d _wind;
        private readonly bool _foldsLift; // the kernel folds Stepanek's lift for this model (k and r in range)
        private readonly double _kappaOverRadiusSquared; // the kernel's: StepanekTable.Kappa / r^2
        private readonly double[] _lanes; // Stepanek's G lane by lane (one batch's scratch; a batch steps on one thread)

        private VectorLaws(
            bool supported, LaneForm drag, LaneForm lift, LaneForm decay, double dragValue, double liftValue, double decayFactor, FlightModel model)
        {
            Supported = supported;
            Drag = drag;
            Lift = lift;
            Decay = decay;
            _factor = model.AerodynamicFactor;
            _negativeFactor = -_factor;
            _dragConstant = -_factor * dragValue;
            _liftConstant = lift == LaneForm.Constant ? _factor * liftValue : liftValue;
            _decayFactor = decayFactor;
            _radius = model.Ball.Radius;
            _gravity = model.Gravity;
            _wind = model.Air.Wind;
            _foldsLift = FlightKernel.FoldsLiftAtScale(_factor, _radius);
            _kappaOverRadiusSquared = Aerodynamics.StepanekTable.Kappa / (_radius * _radius);
            _lanes = new double[Vector<double>.Count];
        }

        /// <summary>
        /// The lanes for a model's laws, each law's form read from the one list of built-in laws (<see cref="LawCatalogue"/>):
        /// not <see cref="Supported"/> where a law has no lane form (<see cref="LaneForm.Scalar"/>) or the wind varies.
        /// </summary>
        internal static VectorLaws For(FlightModel model)
        {
            bool aero = model.Air.Density > 0;
            LawTraits drag = LawCatalogue.TraitsOf(aero ? model.Drag : null);
            LawTraits lift = LawCatalogue.TraitsOf(aero ? model.Lift : null);
            LawTraits decay = LawCatalogue.TraitsOf(model.SpinDecay);
            bool supported = !(model.Air.WindProfile != null && model.Up.LengthSquared > 0) &&
                drag.Lanes != LaneForm.Scalar && lift.Lanes != LaneForm.Scalar && decay.Lanes != LaneForm.Scalar;
            return new VectorLaws(
                supported, Form(drag), Form(lift), Form(decay), drag.Parameter, lift.Parameter, decay.Parameter, model);
        }

        // A law without a lane form counts as off in the fields (the batch then steps ball by ball: Supported is false).
        private static LaneForm Form(in LawTraits traits) => traits.Lanes == LaneForm.Scalar ? LaneForm.Off : traits.Lanes;

        /// <summary>
        /// The acceleration and spin acceleration at velocity v and spin w, lane by lane (the kernel's Rates).
        /// <paramref name="unfolded"/> marks the lanes where the kernel would take the general formula for Stepanek's
        /// lift instead of its folded form (values out of the fold's range): their numbers here are not the kernel's,
        /// and the caller steps those balls one by one.
        /// </summary>
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
            if (Decay == LaneForm.Exponential)
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

            if (Drag == LaneForm.Off && Lift == LaneForm.Off)
            {
                return;
            }

            Vector<double> rx = vx - new Vector<double>(_wind.X), ry = vy - new Vector<double>(_wind.Y), rz = vz - new Vector<double>(_wind.Z);
            Vector<double> speed = Vector.SquareRoot(rx * rx + ry * ry + rz * rz);
            Vector<long> aero = Vector.GreaterThan(speed, new Vector<double>(FlightModel.MinimumAerodynamicSpeed));
            bool needsSpinRate = Lift != LaneForm.Off || Drag == LaneForm.Stepanek;
            Vector<double> spinRate = needsSpinRate ? Vector.SquareRoot(wx * wx + wy * wy + wz * wz) : Vector<double>.Zero;
            // r / s: for Stepanek's drag outside the fold (the folded drag forms it per lane where its table declines), the
            // linear lift and Stepanek's lift outside the fold.
            bool needsRadiusOverSpeed = (Drag == LaneForm.Stepanek && !(Lift == LaneForm.Stepanek && _foldsLift)) ||
                Lift == LaneForm.LinearSpin || (Lift == LaneForm.Stepanek && !_foldsLift);
            Vector<double> inverse = needsRadiusOverSpeed ? new Vector<double>(_radius) / speed : Vector<double>.Zero;

            if (Lift == LaneForm.Constant && Drag != LaneForm.Stepanek)
            {
                // No law reads a spin parameter: the kernel's folded form. Where the lift acts,
                // g + s ((-k C_D) v_rel + (k C_L / |w|) (w x v_rel)); elsewhere the drag alone, g + v_rel ((-k C_D) s).
                Vector<double> liftScale = new Vector<double>(_liftConstant) * (Vector<double>.One / spinRate);
                Vector<long> lifts = aero & Vector.GreaterThan(spinRate, new Vector<double>(FlightModel.MinimumLiftSpinRate));
                Vector<double> ux = (wy * rz - wz * ry) * liftScale, uy = (wz * rx - wx * rz) * liftScale, uz = (wx * ry - wy * rx) * liftScale;
                if (Drag == LaneForm.Constant)
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

            if (Lift == LaneForm.Stepanek && _foldsLift)
            {
                // The kernel's folded Stepanek lift and drag (FlightKernel's TryFoldedRates), the same operations. Lanes outside
                // the range the kernel folds in (where it takes the general formula) are marked for the per-ball step.
                Vector<double> qx = wy * rz - wz * ry, qy = wz * rx - wx * rz, qz = wx * ry - wy * rx;
                Vector<double> squared = rx * rx + ry * ry + rz * rz;
                Vector<double> transverseSquared = qx * qx + qy * qy + qz * qz;
                Vector<double> rt = new Vector<double>(_radius) * Vector.SquareRoot(transverseSquared);
                Vector<double> inverseSpinRate = Vector<double>.One / spinRate;
                Vector<double> liftScale = new Vector<double>(_factor) * inverseSpinRate * speed * rt /
                    (new Vector<double>(2.022) * rt + new Vector<double>(0.981) * squared);
                Vector<long> lifts = aero & Vector.GreaterThan(spinRate, new Vector<double>(FlightModel.MinimumLiftSpinRate));
                var low = new Vector<double>(FlightKernel.FoldMinimumSquare);
                var high = new Vector<double>(FlightKernel.FoldMaximumSquare);
                Vector<long> inRange = Vector.GreaterThanOrEqual(spinRate, new Vector<double>(FlightKernel.FoldMinimum)) &
                    Vector.LessThanOrEqual(spinRate, new Vector<double>(FlightKernel.FoldMaximum)) &
                    Vector.GreaterThanOrEqual(squared, low) & Vector.LessThanOrEqual(squared, high) &
                    (Vector.Equals(transverseSquared, Vector<double>.Zero) |
                        (Vector.GreaterThanOrEqual(transverseSquared, low) & Vector.LessThanOrEqual(transverseSquared, high)));
                unfolded = lifts & ~inRange;
                Vector<double> fx, fy, fz;
                if (Drag == LaneForm.Stepanek)
                {
                    // z = Kappa s^2 / (r |w|)^2 as the kernel forms it, then G lane by lane through the kernel's own function.
                    Vector<double> z = squared * (new Vector<double>(_kappaOverRadiusSquared) * (inverseSpinRate * inverseSpinRate));
                    Vector<double> spinPart = StepanekSpinPartOfSquare(z, speed, spinRate);
                    Vector<double> scale = new Vector<double>(_negativeFactor) * speed;
                    Vector<double> ex = rx * scale, ey = ry * scale, ez = rz * scale;
                    var constant = new Vector<double>(0.508);
                    fx = (gx + ex * constant + spinPart * ex) + qx * liftScale;
                    fy = (gy + ey * constant + spinPart * ey) + qy * liftScale;
                    fz = (gz + ez * constant + spinPart * ez) + qz * liftScale;
                    // Lanes that fly without lift (|w| at or below FlightModel.MinimumLiftSpinRate, below the fold's range): the
                    // kernel's general drag, whose G is read through u = s (1 / (r |w|)), not z from s^2 (a different rounding).
                    // Formed only when such a lane flies.
                    Vector<double> cd = constant + spinPart;
                    if (!Vector.EqualsAll(aero & ~lifts, Vector<long>.Zero))
                    {
                        cd = StepanekDrag(spinRate * (new Vector<double>(_radius) / speed), speed, spinRate);
                    }

                    Vector<double> dragScale = new Vector<double>(_negativeFactor) * cd * speed;
                    ax = Vector.ConditionalSelect(aero, gx + rx * dragScale, gx);
                    ay = Vector.ConditionalSelect(aero, gy + ry * dragScale, gy);
                    az = Vector.ConditionalSelect(aero, gz + rz * dragScale, gz);
                }
                else if (Drag == LaneForm.Constant)
                {
                    Vector<double> dragScale = new Vector<double>(_dragConstant) * speed;
                    ax = Vector.ConditionalSelect(aero, gx + rx * dragScale, gx);
                    ay = Vector.ConditionalSelect(aero, gy + ry * dragScale, gy);
                    az = Vector.ConditionalSelect(aero, gz + rz * dragScale, gz);
                    fx = ax + qx * liftScale;
                    fy = ay + qy * liftScale;
                    fz = az + qz * liftScale;
                }
                else
                {
                    fx = gx + qx * liftScale;
                    fy = gy + qy * liftScale;
                    fz = gz + qz * liftScale;
                }

                ax = Vector.ConditionalSelect(lifts, fx, ax);
                ay = Vector.ConditionalSelect(lifts, fy, ay);
                az = Vector.ConditionalSelect(lifts, fz, az);
                return;
            }

            if (Drag != LaneForm.Off)
            {
                Vector<double> dragScale;
                if (Drag == LaneForm.Constant)
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

            if (Lift != LaneForm.Off)
            {
                Vector<double> unit = Vector<double>.One / speed;
                Vector<double> dx = rx * unit, dy = ry * unit, dz = rz * unit;
                Vector<double> cx = wy * dz - wz * dy, cy = wz * dx - wx * dz, cz = wx * dy - wy * dx;
                Vector<double> liftTimesFactor;
                if (Lift == LaneForm.Constant)
                {
                    liftTimesFactor = new Vector<double>(_liftConstant);
                }
                else
                {
                    Vector<double> transverse = Vector.SquareRoot(cx * cx + cy * cy + cz * cz);
                    Vector<double> sPerp = transverse * inverse;
                    Vector<double> cl = Lift == LaneForm.LinearSpin ? new Vector<double>(_liftConstant) * sPerp : StepanekLift(sPerp);
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
        private Vector<double> StepanekDrag(Vector<double> s, Vector<double> speed, Vector<double> spinRate)
        {
            // Aerodynamics.StepanekDrag.SpinPart itself, lane by lane: its table has no vector form (Vector<T> has no
            // gather in netstandard2.1), and calling the scalar code keeps the lanes the kernel's bits.
            double[] lanes = _lanes;
            for (int i = 0; i < lanes.Length; i++)
            {
                lanes[i] = Aerodynamics.StepanekDrag.SpinPart(speed[i], spinRate[i], _radius, s[i]);
            }

            return new Vector<double>(0.508) + new Vector<double>(lanes);
        }

        // Aerodynamics.StepanekDrag.SpinPartOfSquare (the kernel's folded drag), lane by lane.
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private Vector<double> StepanekSpinPartOfSquare(Vector<double> z, Vector<double> speed, Vector<double> spinRate)
        {
            double[] lanes = _lanes;
            for (int i = 0; i < lanes.Length; i++)
            {
                lanes[i] = Aerodynamics.StepanekDrag.SpinPartOfSquare(z[i], speed[i], spinRate[i], _radius);
            }

            return new Vector<double>(lanes);
        }

        // Aerodynamics.StepanekLift.Evaluate, lane by lane.
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static Vector<double> StepanekLift(Vector<double> s)
        {
            Vector<long> positive = Vector.GreaterThan(s, Vector<double>.Zero);
            return Vector.ConditionalSelect(positive, s / (new Vector<double>(2.022) * s + new Vector<double>(0.981)), Vector<double>.Zero);
        }
    }
}
