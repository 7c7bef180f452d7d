using System;
using System.Runtime.CompilerServices;

namespace MagnusBall
{
    /// <summary>
    /// The neutral atmospheric surface layer's logarithmic wind profile: the wind at height z above the
    /// ground is the reference wind times ln(z / z0) / ln(z_ref / z0), and zero at or below the roughness
    /// length z0. Immutable and safe to share; attach it to <see cref="Air"/> with
    /// <see cref="Air.WithLogarithmicWind"/>.
    /// </summary>
    /// <remarks>
    /// <para>The log law holds in neutral stability over flat, uniform ground (e.g. Stull 1988, "An
    /// Introduction to Boundary Layer Meteorology", section 9.7; Wieringa 1993 for roughness lengths).
    /// Typical z0: 0.0002 m open water, 0.005 m short mown grass or a smooth pitch, 0.03 m open grassland
    /// (the WMO reference), 0.1 m low crops, 0.5-1 m towns. The usual anemometer height is 10 m.</para>
    /// <para>Height is measured along "up" (the flight model's -gravity, normalised) from a point on the
    /// ground, so the profile works in any frame. Below z0 the wind is taken as zero: the log law gives
    /// ln(z/z0) = 0 there, so the profile is continuous; the air-relative velocity simply becomes the
    /// ground velocity.</para>
    /// </remarks>
    public sealed class LogarithmicWindProfile
    {
        /// <summary>The WMO's standard anemometer height, 10 m.</summary>
        internal const double StandardReferenceHeight = 10.0;

        /// <summary>Roughness length of open, flat grassland, 0.03 m (Wieringa 1993; the WMO reference terrain).</summary>
        internal const double OpenGrassRoughnessLength = 0.03;

        private readonly double _inverseLogReference; // 1 / ln(z_ref / z0)

        /// <summary>Creates a profile.</summary>
        /// <param name="referenceHeight">Height at which the reference wind is given, m; finite and &gt; roughnessLength.</param>
        /// <param name="roughnessLength">Aerodynamic roughness length z0, m; finite and &gt; 0.</param>
        /// <param name="groundPoint">Any point on the ground plane (height 0), m; finite. Default: the origin.</param>
        /// <exception cref="ArgumentException">A value is outside its range; the message names it.</exception>
        public LogarithmicWindProfile(
            double referenceHeight = StandardReferenceHeight,
            double roughnessLength = OpenGrassRoughnessLength,
            Vector3d groundPoint = default)
        {
            Require.Positive(roughnessLength, nameof(roughnessLength));
            Require.Positive(referenceHeight, nameof(referenceHeight));
            Require.Finite(groundPoint, nameof(groundPoint));
            if (!(referenceHeight > roughnessLength))
            {
                throw new ArgumentOutOfRangeException(
                    nameof(referenceHeight),
                    referenceHeight,
                    $"referenceHeight must be greater than roughnessLength ({Require.Format(roughnessLength)} m); got {Require.Format(referenceHeight)}.");
            }

            ReferenceHeight = referenceHeight;
            RoughnessLength = roughnessLength;
            GroundPoint = groundPoint;
            _inverseLogReference = 1.0 / PortableMath.Log(referenceHeight / roughnessLength);
        }

        /// <summary>Height at which the reference wind is given, m.</summary>
        internal double ReferenceHeight { get; }

        /// <summary>Roughness length z0, m.</summary>
        internal double RoughnessLength { get; }

        /// <summary>A point on the ground plane, m.</summary>
        internal Vector3d GroundPoint { get; }

        /// <summary>
        /// The wind at <paramref name="height"/> as a fraction of the reference wind: ln(z/z0)/ln(z_ref/z0)
        /// above z0, 0 at or below it. 1 at the reference height. Allocates nothing.
        /// </summary>
        /// <param name="height">Height above the ground, m (any finite value).</param>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal double Factor(double height) =>
            height > RoughnessLength ? PortableMath.Log(height / RoughnessLength) * _inverseLogReference : 0.0;

        /// <summary>Height of <paramref name="position"/> above the ground along <paramref name="up"/> (a unit vector), m.</summary>
        /// <param name="position">The point, m.</param>
        /// <param name="up">The unit up vector.</param>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal double HeightOf(in Vector3d position, in Vector3d up) => Vector3d.Dot(position - GroundPoint, up);

        /// <inheritdoc />
        public override string ToString() =>
            $"LogarithmicWindProfile(z_ref={ReferenceHeight:R} m, z0={RoughnessLength:R} m, ground={GroundPoint})";
    }
}
