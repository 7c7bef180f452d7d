// FlightKernel, part: the rate computations, the right-hand side at one state (Rates): the general formula
// (GeneralRates), the folded form for laws that read only the speed (FoldedRates, TryFoldedRates) and Stepanek's folded
// lift (StepanekLiftFold), and the spin rates. Every RK4 and Dormand-Prince shape takes its stages' rates from here. The
// kernel's entry points are in FlightKernel.cs.
using System.Runtime.CompilerServices;
using MagnusBall.Aerodynamics;

namespace MagnusBall.Integration.Kernels
{
    internal sealed partial class FlightKernel<TDrag, TLift, TDecay>
    {
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
                // on every path, the folded one too (a store and a load on RK4's dependent chain).
                Vector3d at = position, around = spin;

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
    }
}
