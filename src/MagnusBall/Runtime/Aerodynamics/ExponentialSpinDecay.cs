namespace MagnusBall.Aerodynamics
{
    /// <summary>
    /// Exponential spin decay, dw/dt = -w / tau: the spin falls to 1/e of its value in tau seconds.
    /// </summary>
    /// <remarks>
    /// Golf launch monitors quote about 3.3-4 %/s (tau = 25-30 s; TrackMan, Tutelman); Nathan (2008) gives
    /// tau = 5 s for a baseball at 100 mph. See docs/references.md section 3.
    /// </remarks>
    public sealed class ExponentialSpinDecay : ISpinDecayModel
    {
        /// <summary>Creates the law dw/dt = -w / <paramref name="timeConstant"/>.</summary>
        /// <param name="timeConstant">tau, s; finite and &gt; 0.</param>
        /// <exception cref="System.ArgumentOutOfRangeException">tau is not finite or not positive.</exception>
        public ExponentialSpinDecay(double timeConstant)
        {
            TimeConstant = Require.Positive(timeConstant, nameof(timeConstant));
        }

        /// <summary>The time constant tau, s.</summary>
        internal double TimeConstant { get; }

        /// <inheritdoc />
        Vector3d ISpinDecayModel.SpinAcceleration(in Vector3d angularVelocity, in AeroConditions conditions)
        {
            Vector3d rate = angularVelocity * (-1.0 / TimeConstant);
            if (rate.IsFinite || !angularVelocity.IsFinite)
            {
                return rate;
            }

            // 1/tau overflowed (tau below 5.6e-309): divide instead, so a zero component stays 0 (not 0 x infinity).
            double tau = TimeConstant;
            return new Vector3d(-angularVelocity.X / tau, -angularVelocity.Y / tau, -angularVelocity.Z / tau);
        }

        /// <inheritdoc />
        public override string ToString() => $"ExponentialSpinDecay(tau={TimeConstant:R} s)";
    }
}
