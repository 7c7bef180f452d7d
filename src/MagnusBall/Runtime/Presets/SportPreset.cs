using System;
using MagnusBall.Aerodynamics;
using MagnusBall.Contact;

namespace MagnusBall.Presets
{
    /// <summary>
    /// Everything a sport's ball needs for flight: the ball, its drag and lift laws and its spin decay, each
    /// from a cited source (see <see cref="Source"/> and <see cref="SportPresets"/>). Immutable and safe to share.
    /// </summary>
    /// <remarks>
    /// <para>A preset says nothing about the air or the frame: <see cref="CreateModel"/> takes both, so the
    /// same golf ball flies at sea level or at altitude (<see cref="Air.AtAltitude"/>), z-up or y-up.</para>
    /// <para>Where a published bounce model exists for the sport, <see cref="Bounce"/> holds it (tennis: Cross's
    /// slide/grip bounce on a hard court); elsewhere it is null and a scene picks an <see cref="IBounceModel"/>
    /// itself.</para>
    /// </remarks>
    public sealed class SportPreset
    {
        /// <summary>Creates a preset.</summary>
        /// <param name="name">Lower-case, hyphenated name (for example "table-tennis"); not empty.</param>
        /// <param name="ball">The ball.</param>
        /// <param name="drag">The drag law, or null for none.</param>
        /// <param name="lift">The lift law, or null for none.</param>
        /// <param name="spinDecay">The spin-decay law, or null for constant spin.</param>
        /// <param name="source">Where the numbers come from (authors, year, what), or the assumption made.</param>
        /// <param name="bounce">The default bounce model for the sport, or null where none is published here.</param>
        /// <exception cref="ArgumentException">The name or source is empty, or the ball is null.</exception>
        public SportPreset(string name, Ball ball, IDragModel? drag, ILiftModel? lift, ISpinDecayModel? spinDecay, string source, IBounceModel? bounce = null)
        {
            if (string.IsNullOrWhiteSpace(name))
            {
                throw new ArgumentException("name must be a non-empty preset name.", nameof(name));
            }

            if (string.IsNullOrWhiteSpace(source))
            {
                throw new ArgumentException("source must say where the preset's numbers come from.", nameof(source));
            }

            Name = name;
            Ball = Require.NotNull(ball, nameof(ball));
            Drag = drag;
            Lift = lift;
            SpinDecay = spinDecay;
            Source = source;
            Bounce = bounce;
        }

        /// <summary>The preset's name, as <see cref="SportPresets.FromName"/> accepts it.</summary>
        public string Name { get; }

        /// <summary>The ball (mass, radius, inertia factor).</summary>
        public Ball Ball { get; }

        /// <summary>The drag-coefficient law, or null.</summary>
        public IDragModel? Drag { get; }

        /// <summary>The lift-coefficient law, or null.</summary>
        public ILiftModel? Lift { get; }

        /// <summary>The spin-decay law, or null for constant spin.</summary>
        public ISpinDecayModel? SpinDecay { get; }

        /// <summary>
        /// The sport's default bounce model (for tennis, <see cref="CrossBounce.Hard"/>), or null where no bounce
        /// model for the sport is published here.
        /// </summary>
        public IBounceModel? Bounce { get; }

        /// <summary>The sources of the ball's numbers and laws, or the stated assumptions where none was found.</summary>
        public string Source { get; }

        /// <summary>A flight model for this ball in <paramref name="air"/> under <paramref name="gravity"/>.</summary>
        /// <param name="air">The air (see <see cref="Air.FromWeather"/>, <see cref="Air.AtAltitude"/>).</param>
        /// <param name="gravity">The gravity vector, m/s^2 (for example <see cref="MagnusBall.Gravity.YUp"/>).</param>
        /// <exception cref="ArgumentException">air is null or gravity is not finite.</exception>
        public FlightModel CreateModel(Air air, Vector3d gravity) => new FlightModel(Ball, air, gravity, Drag, Lift, SpinDecay);

        /// <summary>A copy with another ball (the name and laws are kept; the source notes the change).</summary>
        /// <param name="ball">The ball.</param>
        public SportPreset WithBall(Ball ball) => new SportPreset(Name, ball, Drag, Lift, SpinDecay, Source + " Ball overridden.", Bounce);

        /// <summary>A copy with another drag law (null for none).</summary>
        /// <param name="drag">The drag law.</param>
        public SportPreset WithDrag(IDragModel? drag) => new SportPreset(Name, Ball, drag, Lift, SpinDecay, Source + " Drag overridden.", Bounce);

        /// <summary>A copy with another lift law (null for none).</summary>
        /// <param name="lift">The lift law.</param>
        public SportPreset WithLift(ILiftModel? lift) => new SportPreset(Name, Ball, Drag, lift, SpinDecay, Source + " Lift overridden.", Bounce);

        /// <summary>A copy with another spin-decay law (null for constant spin).</summary>
        /// <param name="spinDecay">The spin-decay law.</param>
        public SportPreset WithSpinDecay(ISpinDecayModel? spinDecay) =>
            new SportPreset(Name, Ball, Drag, Lift, spinDecay, Source + " Spin decay overridden.", Bounce);

        /// <summary>A copy with another default bounce model (null for none).</summary>
        /// <param name="bounce">The bounce model.</param>
        public SportPreset WithBounce(IBounceModel? bounce) =>
            new SportPreset(Name, Ball, Drag, Lift, SpinDecay, Source + " Bounce overridden.", bounce);

        /// <inheritdoc />
        public override string ToString() =>
            $"SportPreset({Name}: {Ball}, drag={Drag?.ToString() ?? "off"}, lift={Lift?.ToString() ?? "off"}, spinDecay={SpinDecay?.ToString() ?? "off"})";
    }
}
