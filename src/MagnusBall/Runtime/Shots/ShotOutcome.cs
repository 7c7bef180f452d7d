namespace MagnusBall.Shots
{
    /// <summary>How a shot ends against its sport's standard geometry (<see cref="TennisCourt"/>, <see cref="TableTennisTable"/>, <see cref="SoccerGoal"/>).</summary>
    public enum ShotOutcome
    {
        /// <summary>Good: it lands in the opponent's court or half of the table (lines and edges included), or goes into the goal.</summary>
        In,

        /// <summary>It comes down before the net or the goal line.</summary>
        Short,

        /// <summary>It hits the net (its centre passes the net lower than one radius above the net's top).</summary>
        Net,

        /// <summary>It lands beyond the far baseline or end line (long), or does not land within the flight's time limit.</summary>
        Out,

        /// <summary>It lands beyond a sideline, or passes the goal line outside a post.</summary>
        Wide,

        /// <summary>It passes the goal line over the crossbar.</summary>
        Over,

        /// <summary>It strikes a goalpost or the crossbar.</summary>
        Woodwork,
    }
}
