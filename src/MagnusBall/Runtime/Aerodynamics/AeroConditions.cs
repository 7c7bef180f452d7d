using System.Runtime.CompilerServices;

namespace MagnusBall.Aerodynamics
{
    /// <summary>
    /// What a coefficient model may read at one instant: the air-relative speed, the spin, the spin
    /// parameters and the Reynolds number. Built once per derivative evaluation by <see cref="FlightModel"/>.
    /// </summary>
    /// <remarks>
    /// The spin parameter S = r|w|/s is what drag models read; the transverse spin parameter
    /// S_perp = r|w x v_hat|/s, built from the spin component across the flight, is what lift models read
    /// (see docs/references.md section 1 and docs/physics.md). When the air-relative speed is
    /// zero both parameters are reported as 0 (they are undefined there, and no aerodynamic force acts).
    /// For finite arguments no derived value is NaN, and each is finite whenever its true value fits in a double
    /// (one beyond double.MaxValue, such as the spin parameter at a speed of 1e-300 m/s, is +infinity).
    /// </remarks>
    public readonly struct AeroConditions
    {
        /// <summary>Air-relative speed s = |v - wind|, m/s.</summary>
        public readonly double Speed;

        /// <summary>Spin rate |w|, rad/s.</summary>
        public readonly double SpinRate;

        /// <summary>Spin rate across the flight direction |w x v_hat|, rad/s.</summary>
        public readonly double TransverseSpinRate;

        /// <summary>Ball radius r, m.</summary>
        public readonly double Radius;

        /// <summary>Air density, kg/m^3.</summary>
        public readonly double Density;

        /// <summary>Spin parameter S = r|w|/s (dimensionless); 0 when s = 0.</summary>
        public readonly double SpinParameter;

        /// <summary>Transverse spin parameter S_perp = r|w x v_hat|/s (dimensionless); 0 when s = 0.</summary>
        public readonly double TransverseSpinParameter;

        /// <summary>Reynolds number rho s (2r) / mu (dimensionless).</summary>
        public readonly double ReynoldsNumber;

        /// <summary>
        /// Creates the conditions; the spin parameters are derived from the arguments. A value built once per derivative
        /// evaluation, so its arguments are not checked: the model passes checked ones (a NaN radius gives NaN parameters).
        /// </summary>
        /// <param name="speed">Air-relative speed, m/s (&gt;= 0).</param>
        /// <param name="spinRate">|w|, rad/s.</param>
        /// <param name="transverseSpinRate">|w x v_hat|, rad/s.</param>
        /// <param name="radius">Ball radius, m.</param>
        /// <param name="density">Air density, kg/m^3.</param>
        /// <param name="dynamicViscosity">Air dynamic viscosity, Pa s (&gt; 0).</param>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public AeroConditions(double speed, double spinRate, double transverseSpinRate, double radius, double density, double dynamicViscosity)
        {
            Speed = speed;
            SpinRate = spinRate;
            TransverseSpinRate = transverseSpinRate;
            Radius = radius;
            Density = density;
            if (speed > 0)
            {
                double inverse = radius / speed;
                SpinParameter = spinRate * inverse;
                TransverseSpinParameter = transverseSpinRate * inverse;
                if (!double.IsFinite(SpinParameter) || !double.IsFinite(TransverseSpinParameter))
                {
                    // r / s or its product overflowed (a tiny speed): w / s first, and 0 spin stays 0 (never 0 x infinity).
                    SpinParameter = Overflow.Multiply(Ratio(spinRate, speed), radius);
                    TransverseSpinParameter = Overflow.Multiply(Ratio(transverseSpinRate, speed), radius);
                }
            }
            else
            {
                SpinParameter = 0;
                TransverseSpinParameter = 0;
            }

            ReynoldsNumber = density * speed * 2 * radius / dynamicViscosity;
            if (!double.IsFinite(ReynoldsNumber))
            {
                // Grouped so that no intermediate overflows where the result fits; 0 density or speed gives 0, never NaN.
                ReynoldsNumber = Overflow.Multiply(Overflow.Multiply(density / dynamicViscosity, speed), 2 * radius);
            }
        }

        // w / s; when both are infinite (beyond double.MaxValue) their ratio is unknown and taken as 1, never NaN.
        private static double Ratio(double spin, double speed)
        {
            double ratio = spin / speed;
            return double.IsNaN(ratio) && !double.IsNaN(spin) && !double.IsNaN(speed) ? 1 : ratio;
        }

        /// <summary>
        /// The flight kernel's constructor: every field given, already computed (by the same expressions as the public
        /// constructor), or 0 where no law of the model reads it.
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal AeroConditions(
            double speed, double spinRate, double transverseSpinRate, double radius, double density,
            double spinParameter, double transverseSpinParameter, double reynoldsNumber)
        {
            Speed = speed;
            SpinRate = spinRate;
            TransverseSpinRate = transverseSpinRate;
            Radius = radius;
            Density = density;
            SpinParameter = spinParameter;
            TransverseSpinParameter = transverseSpinParameter;
            ReynoldsNumber = reynoldsNumber;
        }

        /// <summary>Spin rate in revolutions per minute, |w| 60 / (2 pi).</summary>
        internal double SpinRpm => SpinRate * (60.0 / (2.0 * System.Math.PI));
    }

    /// <summary>A drag-coefficient law C_D(conditions). Implementations are immutable and thread-safe.</summary>
    public interface IDragModel
    {
        /// <summary>The drag coefficient C_D (dimensionless, &gt;= 0) for these conditions.</summary>
        /// <param name="conditions">Speed, spin and Reynolds number at this instant.</param>
        double DragCoefficient(in AeroConditions conditions);
    }

    /// <summary>
    /// A lift (Magnus) coefficient law C_L(conditions). Implementations are immutable and thread-safe.
    /// The force it produces is 1/2 rho A C_L s^2 (w x v_hat)/|w|, so a positive C_L pushes the ball
    /// toward w x v (the classic Magnus direction).
    /// </summary>
    public interface ILiftModel
    {
        /// <summary>The lift coefficient C_L (dimensionless) for these conditions.</summary>
        /// <param name="conditions">Speed, spin and Reynolds number at this instant.</param>
        double LiftCoefficient(in AeroConditions conditions);
    }

    /// <summary>
    /// A spin-decay law dw/dt = f(w, conditions). Implementations are immutable and thread-safe.
    /// </summary>
    public interface ISpinDecayModel
    {
        /// <summary>The angular acceleration dw/dt, rad/s^2, for this spin and these conditions.</summary>
        /// <param name="angularVelocity">The current angular velocity w, rad/s.</param>
        /// <param name="conditions">Speed, spin and Reynolds number at this instant.</param>
        Vector3d SpinAcceleration(in Vector3d angularVelocity, in AeroConditions conditions);
    }
}
