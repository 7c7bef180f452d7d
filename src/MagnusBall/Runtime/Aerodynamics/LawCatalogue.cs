// LawCatalogue: the one list of the built-in coefficient laws. For each law kind, once: the struct the flight kernel runs
// it through (Aerodynamics/CoefficientLaws.cs), its form in the ball batch's Vector<double> lanes (or none) and the bound
// the stability shortcut reads. The three consumers read it: FlightKernelFactory (the kernel), VectorLaws.For (the
// batch's lanes) and FlightModel's constructor (the bounds). The conformance test runs every law listed here
// (tests/MagnusBall.Tests/Integration/ConformanceTests.cs). How to add a law: docs/architecture.md, "The spec".
using System;

namespace MagnusBall.Aerodynamics
{
    /// <summary>How a law runs in the ball batch's <c>Vector&lt;double&gt;</c> lanes (Batch/VectorLaws).</summary>
    internal enum LaneForm
    {
        /// <summary>No vector form: a model with this law steps its balls one by one (the kernel's scalar step).</summary>
        Scalar = 0,

        /// <summary>The term is off (no law, or no air).</summary>
        Off,

        /// <summary>A constant coefficient (<see cref="LawTraits.Parameter"/>: C_D or C_L).</summary>
        Constant,

        /// <summary>C_L = slope S_perp (<see cref="LawTraits.Parameter"/>: the slope).</summary>
        LinearSpin,

        /// <summary>Stepanek's fit (drag or lift).</summary>
        Stepanek,

        /// <summary>dw/dt = c w (<see cref="LawTraits.Parameter"/>: c = -1 / tau).</summary>
        Exponential,
    }

    /// <summary>What the consumers other than the kernel need of a law: its bound and its lane form.</summary>
    internal readonly struct LawTraits
    {
        /// <summary>An absent term: bound 0, off in the lanes.</summary>
        internal static readonly LawTraits Off = new LawTraits(0, LaneForm.Off);

        /// <summary>A law with no known bound and no vector form.</summary>
        internal static readonly LawTraits Scalar = new LawTraits(null, LaneForm.Scalar);

        internal LawTraits(double? bound, LaneForm lanes, double parameter = 0)
        {
            Bound = bound;
            Lanes = lanes;
            Parameter = parameter;
        }

        /// <summary>
        /// A drag or lift law: at least |C| for every input; a spin decay: at least |dw/dt| / |w| for every input. Null
        /// where no bound is worked out (FlightModel.StiffnessSurelyBelow then computes the rate).
        /// </summary>
        internal double? Bound { get; }

        /// <summary>The law's form in the batch's lanes.</summary>
        internal LaneForm Lanes { get; }

        /// <summary>The lanes' constant (see <see cref="LaneForm"/>); 0 where the form has none.</summary>
        internal double Parameter { get; }
    }

    /// <summary>Called by <see cref="LawCatalogue.Drag"/> with the law's kernel struct and traits (a struct: no virtual call, every instantiation known ahead of time).</summary>
    internal interface IDragVisitor<out TResult>
    {
        TResult Visit<TDrag>(TDrag law, in LawTraits traits)
            where TDrag : struct, IDragLaw;
    }

    /// <summary>Called by <see cref="LawCatalogue.Lift"/> (see <see cref="IDragVisitor{TResult}"/>).</summary>
    internal interface ILiftVisitor<out TResult>
    {
        TResult Visit<TLift>(TLift law, in LawTraits traits)
            where TLift : struct, ILiftLaw;
    }

    /// <summary>Called by <see cref="LawCatalogue.SpinDecay"/> (see <see cref="IDragVisitor{TResult}"/>).</summary>
    internal interface ISpinDecayVisitor<out TResult>
    {
        TResult Visit<TDecay>(TDecay law, in LawTraits traits)
            where TDecay : struct, ISpinDecayLaw;
    }

    /// <summary>
    /// The built-in laws, each listed once: a <c>case</c> that names its kernel struct and its traits, and an example
    /// the conformance test flies. A law not listed (a user's own) runs through its interface (<see cref="InterfaceDrag"/>,
    /// <see cref="InterfaceLift"/>, <see cref="InterfaceSpinDecay"/>) with no bound and no lane form: correct, without
    /// the struct's inlining. The visitors are struct type parameters, so the JIT (and IL2CPP ahead of time) sees every
    /// kernel type a model can build, as the type switches this replaces did.
    /// </summary>
    internal static class LawCatalogue
    {
        // Stepanek drag: 0.508 + (22.053 + ...)^(-2/5) <= 0.508 + 22.053^(-2/5) = 0.7981; Stepanek lift: S / (2.022 S + 0.981)
        // < 1/2.022 = 0.4946 (Stepanek 1988's fits, Aerodynamics/Stepanek.cs).
        private const double StepanekDragBound = 0.8, StepanekLiftBound = 0.5;

        /// <summary>The drag law <paramref name="law"/> (null: no drag) as its kernel struct and traits, given to <paramref name="visitor"/>.</summary>
        internal static TResult Drag<TVisitor, TResult>(IDragModel? law, ref TVisitor visitor)
            where TVisitor : struct, IDragVisitor<TResult>
        {
            switch (law)
            {
                case null: return visitor.Visit(default(NoDrag), LawTraits.Off);
                case ConstantDrag c: return visitor.Visit(new ConstantDragLaw(c.Value), new LawTraits(Math.Abs(c.Value), LaneForm.Constant, c.Value));
                // The lanes call the kernel's scalar G (StepanekDrag.SpinPart, SpinPartOfSquare) with the kernel's inputs.
                case StepanekDrag _: return visitor.Visit(default(StepanekDragLaw), new LawTraits(StepanekDragBound, LaneForm.Stepanek));
                case LinearSpinDrag l: return visitor.Visit(new LinearSpinDragLaw(l), LawTraits.Scalar);
                case NathanBaseballDrag _: return visitor.Visit(default(NathanBaseballDragLaw), LawTraits.Scalar);
                case GoffCarreSoccerDrag _: return visitor.Visit(default(GoffCarreSoccerDragLaw), LawTraits.Scalar);
                case GolfSpinReynoldsDrag _: return visitor.Visit(new InterfaceDrag(law), LawTraits.Scalar); // through its interface (reads Re)
                // Bound: the table's largest C_D (linear interpolation stays inside its knots).
                case ContiTableTennisDrag _: return visitor.Visit(default(ContiTableTennisDragLaw), new LawTraits(ContiTableTennisDrag.Largest, LaneForm.Scalar));
                case GolfNaruoUsgaLaw _: return visitor.Visit(new InterfaceDrag(law), new LawTraits(GolfNaruoUsgaLaw.DragBound, LaneForm.Scalar)); // interface (reads Re)
                default: return visitor.Visit(new InterfaceDrag(law), LawTraits.Scalar);
            }
        }

        /// <summary>The lift law <paramref name="law"/> (null: no Magnus force) as its kernel struct and traits.</summary>
        internal static TResult Lift<TVisitor, TResult>(ILiftModel? law, ref TVisitor visitor)
            where TVisitor : struct, ILiftVisitor<TResult>
        {
            switch (law)
            {
                case null: return visitor.Visit(default(NoLift), LawTraits.Off);
                case ConstantLift c: return visitor.Visit(new ConstantLiftLaw(c.Value), new LawTraits(Math.Abs(c.Value), LaneForm.Constant, c.Value));
                case StepanekLift _: return visitor.Visit(default(StepanekLiftLaw), new LawTraits(StepanekLiftBound, LaneForm.Stepanek));
                case LinearSpinLift l: return visitor.Visit(new LinearSpinLiftLaw(l.Slope), new LawTraits(null, LaneForm.LinearSpin, l.Slope));
                case NathanBaseballLift _: return visitor.Visit(default(NathanBaseballLiftLaw), LawTraits.Scalar);
                case PiecewiseLinearLift t: return visitor.Visit(new PiecewiseLinearLiftLaw(t), LawTraits.Scalar);
                case GolfSpinReynoldsLift _: return visitor.Visit(new InterfaceLift(law), LawTraits.Scalar); // through its interface (reads Re)
                // Bound: (8/3) x the fit's largest C_M (0.383) x S held at 10.
                case ContiTableTennisLift _: return visitor.Visit(default(ContiTableTennisLiftLaw), new LawTraits(ContiTableTennisLift.Largest, LaneForm.Scalar));
                case GolfNaruoUsgaLaw _: return visitor.Visit(new InterfaceLift(law), new LawTraits(GolfNaruoUsgaLaw.LiftBound, LaneForm.Scalar)); // interface (reads Re)
                default: return visitor.Visit(new InterfaceLift(law), LawTraits.Scalar);
            }
        }

        /// <summary>The spin-decay law <paramref name="law"/> (null: constant spin) as its kernel struct and traits.</summary>
        internal static TResult SpinDecay<TVisitor, TResult>(ISpinDecayModel? law, ref TVisitor visitor)
            where TVisitor : struct, ISpinDecayVisitor<TResult>
        {
            switch (law)
            {
                case null: return visitor.Visit(default(NoSpinDecay), LawTraits.Off);
                case ExponentialSpinDecay e:
                    return visitor.Visit(new ExponentialSpinDecayLaw(e.TimeConstant), new LawTraits(1.0 / e.TimeConstant, LaneForm.Exponential, -1.0 / e.TimeConstant));
                case SpeedProportionalSpinDecay s: return visitor.Visit(new SpeedProportionalSpinDecayLaw(s.RatePerMetre), LawTraits.Scalar);
                default: return visitor.Visit(new InterfaceSpinDecay(law), LawTraits.Scalar);
            }
        }

        /// <summary>The traits of a drag law (null: none).</summary>
        internal static LawTraits TraitsOf(IDragModel? law)
        {
            var traits = default(TraitsVisitor);
            return Drag<TraitsVisitor, LawTraits>(law, ref traits);
        }

        /// <summary>The traits of a lift law (null: none).</summary>
        internal static LawTraits TraitsOf(ILiftModel? law)
        {
            var traits = default(TraitsVisitor);
            return Lift<TraitsVisitor, LawTraits>(law, ref traits);
        }

        /// <summary>The traits of a spin-decay law (null: none).</summary>
        internal static LawTraits TraitsOf(ISpinDecayModel? law)
        {
            var traits = default(TraitsVisitor);
            return SpinDecay<TraitsVisitor, LawTraits>(law, ref traits);
        }

        /// <summary>
        /// One instance of every law listed above (parameters as the presets and the literature use them), which the
        /// conformance test flies in every combination; a new law gets its line here beside its case.
        /// </summary>
        internal static IDragModel[] DragExamples() => new IDragModel[]
        {
            ConstantDrag.ThesisTennis,
            StepanekDrag.Instance,
            LinearSpinDrag.GolfSmitsSmith,
            NathanBaseballDrag.Instance,
            GoffCarreSoccerDrag.Instance,
            GolfSpinReynoldsDrag.BearmanHarvey,
            ContiTableTennisDrag.Instance,
            GolfNaruoUsgaLaw.Instance,
        };

        /// <summary>One instance of every lift law listed above.</summary>
        internal static ILiftModel[] LiftExamples() => new ILiftModel[]
        {
            ConstantLift.ThesisTennis,
            StepanekLift.Instance,
            LinearSpinLift.Cross2020Tennis,
            NathanBaseballLift.Instance,
            PiecewiseLinearLift.GolfSmitsSmith,
            GolfSpinReynoldsLift.BearmanHarvey,
            ContiTableTennisLift.Instance,
            GolfNaruoUsgaLaw.Instance,
        };

        /// <summary>One instance of every spin-decay law listed above.</summary>
        internal static ISpinDecayModel[] SpinDecayExamples() => new ISpinDecayModel[]
        {
            new ExponentialSpinDecay(20),
            SpeedProportionalSpinDecay.TennisCrossLindsey,
        };

        private struct TraitsVisitor : IDragVisitor<LawTraits>, ILiftVisitor<LawTraits>, ISpinDecayVisitor<LawTraits>
        {
            LawTraits IDragVisitor<LawTraits>.Visit<TDrag>(TDrag law, in LawTraits traits) => traits;

            LawTraits ILiftVisitor<LawTraits>.Visit<TLift>(TLift law, in LawTraits traits) => traits;

            LawTraits ISpinDecayVisitor<LawTraits>.Visit<TDecay>(TDecay law, in LawTraits traits) => traits;
        }
    }
}
