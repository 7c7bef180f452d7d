using System;

namespace MagnusBall.Aerodynamics
{
    /// <summary>
    /// Spin decay proportional to the air-relative speed, dw/dt = -k s w: the spin falls by the same fraction
    /// per metre of air travelled, exp(-k) per metre, whatever the speed.
    /// </summary>
    /// <remarks>
    /// <para>This is the form a friction torque proportional to the dynamic pressure and to the surface speed
    /// r|w| gives: Nathan (2008, "The Effect of Spin-Down on the Flight of a Baseball", an unpublished note of July 14,
    /// 2008, not his Am. J. Phys. 76:119 paper) writes I dw/dt = -1/2 k R rho A C_L s^2 with C_L ~ S, i.e.
    /// dw/dt = -0.020 k s w with s in mph; "as a numerical example", k = 0.1 gives a time constant of 5 s at 100 mph,
    /// k = 1/(5 s x 44.704 m/s) = 0.004474 per metre (<see cref="BaseballNathan"/>). That k is an illustration, not a
    /// measurement: Nathan's trajectory calculator takes tau with the same 1/v scaling as an input (30 s at 100 mph in
    /// one sheet of a public copy, 10,000 s, no decay, in another), and no measured baseball spin decay was found. Tennis: Cross &amp; Lindsey (2014) measured about 2 % of the spin lost
    /// over 6.4 m of flight, k = -ln(0.98)/6.4 m = 0.003157 per metre (<see cref="TennisCrossLindsey"/>).
    /// See docs/references.md section 3.</para>
    /// </remarks>
    public sealed class SpeedProportionalSpinDecay : ISpinDecayModel
    {
        /// <summary>Creates the law dw/dt = -<paramref name="ratePerMetre"/> s w.</summary>
        /// <param name="ratePerMetre">k, 1/m; finite and &gt;= 0.</param>
        /// <exception cref="ArgumentOutOfRangeException">k is negative or not finite.</exception>
        public SpeedProportionalSpinDecay(double ratePerMetre)
        {
            RatePerMetre = Require.NonNegative(ratePerMetre, nameof(ratePerMetre));
        }

        /// <summary>k, 1/m: the spin falls by a factor exp(-k) per metre of air travelled.</summary>
        internal double RatePerMetre { get; }

        /// <summary>
        /// The law that loses <paramref name="fraction"/> of the spin over <paramref name="distanceMetres"/> of
        /// air travelled: k = -ln(1 - fraction) / distance.
        /// </summary>
        /// <param name="fraction">Fraction lost, in [0, 1).</param>
        /// <param name="distanceMetres">Distance, m; finite and &gt; 0.</param>
        /// <exception cref="ArgumentOutOfRangeException">A value is out of range; the message names it.</exception>
        public static SpeedProportionalSpinDecay FromLossOverDistance(double fraction, double distanceMetres)
        {
            Require.Positive(distanceMetres, nameof(distanceMetres));
            if (!double.IsFinite(fraction) || fraction < 0 || fraction >= 1)
            {
                throw new ArgumentOutOfRangeException(nameof(fraction), fraction, $"fraction must be in [0, 1); got {Require.Format(fraction)}.");
            }

            return new SpeedProportionalSpinDecay(-PortableMath.Log(1 - fraction) / distanceMetres);
        }

        /// <summary>Tennis, Cross &amp; Lindsey (2014): 2 % spin loss over 6.4 m, k = 0.003157 per metre.</summary>
        public static SpeedProportionalSpinDecay TennisCrossLindsey { get; } = FromLossOverDistance(0.02, 6.4);

        /// <summary>
        /// Baseball, Nathan (2008 note): time constant 5 s at 100 mph (44.704 m/s), k = 0.004474 per metre (his illustration, not a measurement).
        /// </summary>
        public static SpeedProportionalSpinDecay BaseballNathan { get; } = new SpeedProportionalSpinDecay(1.0 / (5.0 * 44.704));

        /// <inheritdoc />
        Vector3d ISpinDecayModel.SpinAcceleration(in Vector3d angularVelocity, in AeroConditions conditions) =>
            Overflow.Multiply(angularVelocity, Overflow.Multiply(-RatePerMetre, conditions.Speed));

        /// <inheritdoc />
        public override string ToString() => $"SpeedProportionalSpinDecay(k={RatePerMetre:R} /m)";
    }
}
