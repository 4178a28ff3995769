// The table of diagnostic codes: the one source of the Code enum (diagnostics.h), of
// docs/diagnostics.md (diagnosticsMarkdown, kept equal by tests/unit/diagnostics_test.cpp) and of
// the rules of a SARIF report (ci_report.cpp).
//
// X(number, Name, default severity, severity as documented, meaning)
//   number   the code users see: 302 is K0302. The hundreds are the family (1 reading the text,
//            2 words and modal state, 3 arcs, 4 motion, 5 program flow, 6 the geometry of the cut,
//            7 numbers, 8 outputs and options, 9 the wire offset); a code has one meaning for ever,
//            and a new meaning takes a new number.
//   Name     Code::Name.
//   default  the severity a SARIF rule gives (the first the documented words name).
//   words    the severities as documented: "error", "warning", "error/warning", ...
//   meaning  one line of Markdown: what it says and when (backticks for code, \| for a bar).
#pragma once

// One row a line, however long, so that a row reads (and diffs) whole.
// clang-format off
#define KERF_DIAGNOSTIC_TABLE(X) \
  /* Lexical and syntax; drawings and curves */ \
  X(101, UnterminatedComment, Error, "error", "a `(` comment not closed on its line") \
  X(102, ExpectedNumber, Error, "error", "a word letter with no number (`X`, `GO1`, `XNAN`)") \
  X(103, MalformedNumber, Error, "error", "a second decimal point, a sign inside a number") \
  X(104, ExponentNotation, Error, "error", "`1e5` style numbers") \
  X(105, NumberOutOfRange, Error, "error", "more than 18 digits, or \\|value\\| ≥ 1e9") \
  X(106, UnexpectedCharacter, Error, "error", "a character that is no part of a block (`#`, `,`, control bytes, a number without a letter)") \
  X(107, UnknownWord, Error, "error", "a letter that is no ISO wire word (B, W); hints at 3B code") \
  X(108, RepeatedWord, Error, "error", "the same letter twice in a block (G and M may repeat)") \
  X(109, NestedComment, Error, "error", "`(` inside a comment") \
  X(110, MalformedSetting, Error, "error", "`H001 =` with no value") \
  X(111, TooManyMCodes, Error, "error", "more than four M codes, or six codes of the machine profile, in one block (none is dropped silently)") \
  X(112, DecimalComma, Error, "error", "a comma where the decimal point belongs (`F12,9285`); the help gives the number probably meant") \
  X(113, MacroStatement, Error, "error", "macro B (`#100 = …`, `WHILE`, `IF`, `GOTO`, `END`) is not run; one for the file, at the first, counting the rest") \
  X(114, BlockTooLong, Error, "error", "a line of more than 65,535 characters; it is not read") \
  X(120, ThreeBSyntax, Error, "error", "a malformed 3B record (a lost B, a sign or point in a field, an unknown Z, no G)") \
  X(121, DxfSyntax, Error, "error", "a malformed or truncated DXF file, at its line (binary: byte offset) and group code") \
  X(122, DxfEntity, Warning, "warning/error", "a DXF entity that cannot become a contour (zero radius, a spline whose knots do not fit, an INSERT of a block that is not there, nesting too deep); error: INSERTs that expand past the budget, refused before expanding further") \
  X(123, DxfSkipped, Note, "note", "DXF entities that carry no contour (text, dimensions, hatches, points), counted by type") \
  X(124, DxfUnits, Note, "note", "the drawing's $INSUNITS, and the scale Kerf read it with") \
  X(125, ContourOpen, Warning, "warning/error", "a drawing's chain of elements that does not close: its gap and where its ends are; error: `kerf cam` asked to cut it as a part") \
  X(130, CurveSyntax, Error, "error", "a curve (`--curve`, a `.curve` file) whose expression does not parse or evaluate to a finite point, whose range is empty, or whose point list has a line that is not two numbers") \
  X(131, CurveFit, Note, "note/error", "the biarcs a curve was fitted with (spans, largest error); error: a curve that cannot be fitted within the tolerance (a cusp, a corner) or needs more spans than allowed") \
  X(132, DrawingOutOfRange, Error, "error", "a drawing's entity beyond Kerf's range: a point or size farther than 1e6 mm (a kilometre), an INSERT scale of 0 or beyond 1e6, an ellipse whose ratio is outside (0, 1]; refused at its line, the rest of the drawing read") \
  /* Words and modal state */ \
  X(201, UnknownGCode, Error, "error", "a G code neither the standard set nor the machine profile knows; the help names the built-in profiles that know it") \
  X(202, UnknownMCode, Warning, "warning", "an M code neither the standard set nor the machine profile knows (once per code); taken as having no effect on the path") \
  X(203, ModalGroupConflict, Error, "error", "two G codes of one modal group in a block") \
  X(204, PlaneNotSupported, Error, "error", "G18/G19") \
  X(205, WordIgnored, Warning, "warning", "a letter that means nothing in this program (A, K, Q, T, W, Z), once per letter") \
  X(206, WordNotInDialect, Error, "error", "a word of another 4-axis dialect than the one in force (U/V, `:`, G50–G52, G140–G142, X Y after U V, ...); the help names `--dialect`") \
  X(207, RadiusAndCentre, Error, "error", "R and I/J in one arc") \
  X(208, DwellWithoutTime, Error, "error", "G04 without P or X") \
  X(209, SetPositionWithoutAxis, Error, "error", "G92 without coordinates (a bare G92 is the origin under the robofil profile)") \
  X(210, WireOffsetNotApplied, Warning, "warning", "G41/G42 with a register no table gives: the moves under it are shown on their programmed contour (K0901 says where the offset was applied)") \
  X(211, WireOffsetUnknown, Warning, "warning", "bare G41/G42 and no `--offset`") \
  X(212, NoMotionMode, Error, "error", "coordinates before any G00–G03") \
  X(213, WorkOffsetIgnored, Warning, "warning", "G54–G59 taken as zero") \
  X(214, BadFeed, Warning, "warning", "F ≤ 0") \
  /* 4-axis taper: dialects, heights, pairing */ \
  X(215, DialectAmbiguous, Error, "error", "the 4-axis words fit more than one dialect (docs/taper.md lists the evidence)") \
  X(216, DialectChosen, Note, "note", "the dialect detected and the evidence for it") \
  X(217, HeightsMissing, Error, "error/warning", "a taper program without an upper plane height, or an upper plane not above the lower; warning: a converted taper program written without them") \
  X(218, TaperAngleTooLarge, Error, "error", "\\|A\\| or \\|T\\| above 45°") \
  X(219, TaperOnArc, Error, "error", "a taper started (G51/G52) or ended (G50) on an arc") \
  X(220, BlockCountMismatch, Error, "error", "two-file input with different move counts") \
  X(221, OffsetCollapses, Warning, "warning", "a taper offset shrinks an arc to a sharp corner; error: it swallows an element, or neighbours never meet") \
  X(222, CentreOnStraightMove, Warning, "warning", "I J R (or K L) on a straight move, ignored") \
  X(223, DwellWordsIgnored, Warning, "warning", "coordinates in a G04 block, ignored") \
  X(224, TaperAngleTwice, Error, "error", "A and T in one block") \
  X(225, ParameterMissing, Warning, "warning", "a code that takes P has none (M101 without the thickness)") \
  X(226, UpperSideMissing, Error, "error", "inside G141/G142 a move without its `:` upper side") \
  X(227, TwoFileNotPlain, Error, "error", "two-file input where one program is itself a 4-axis program") \
  X(228, NegativeDwell, Error, "error", "G04 with a negative time") \
  X(229, OffsetOnArc, Error, "error", "the wire offset started (G41/G42) or cancelled (G40) on an arc") \
  /* Machine profiles (machine.h) */ \
  X(230, MachineDetected, Note, "note", "the machine profile read with, and the evidence for it and for the conventions taken from the program (docs/machines.md)") \
  X(231, MachineCode, Note, "note", "a code the machine profile knows, with what it does there (once per code)") \
  X(232, CodeNotModelled, Warning, "warning", "a code the profile knows that changes the path in a way Kerf does not model") \
  X(233, PositionUnknown, Note, "note", "the wire goes where only the machine knows (G28, edge sensing, a register or macro value, a macro call) until a block gives the position again; error when cut moves in that stretch cannot be checked. One for the stretch") \
  X(234, DirectionWord, Error, "error", "`Y+` (a direction) outside an edge-sensing code") \
  X(235, UpperAxesNamedUZ, Error, "error", "U with Z and no V anywhere: the second plane may be named U Z; say so with `--upper-axes uz` (the blocks are not guessed at)") \
  X(236, PolarNotSupported, Warning, "warning/error", "a mill-turn program ends inside polar interpolation (no G13.1/G113); error: polar interpolation under a profile that does not read it, the section not read") \
  X(237, RotaryJump, Error, "error (warning for a rapid)", "a C step longer than the shortest way (docs/polar.md)") \
  X(238, PolarAxisValue, Note, "note", "how a mill-turn program's polar frame or X/C spirals were drawn") \
  X(239, HomePositionTaken, Note, "note", "G28/G30 go to the machine profile's home position (`home`, default the origin), drawn as rapids; once per program") \
  X(240, CornerNotMade, Error, "error", "a corner `,R r` or `,C c` (or NCVC's bare R on a cut block) that cannot be made: no cut move follows, the elements meet tangent or turn back, r or c is more than an element has, or the program's dialect has its own upper contour; nothing is drawn in its place") \
  X(241, RotaryAxisNotModelled, Note, "note", "a rotary axis word that only homes (`G28 B`): Kerf does not model the axis (a B that moves while cutting is K0107)") \
  /* Arcs */ \
  X(301, ArcWithoutCentre, Error, "error", "an arc with neither I J nor R") \
  X(302, RadiusTooSmall, Error, "error", "\\|R\\| shorter than half the chord") \
  X(303, FullCircleWithRadius, Error, "error", "an R arc that ends where it starts") \
  X(304, ArcEndOffCircle, Error, "error", "the end is off the circle beyond LinuxCNC's tolerance") \
  X(305, ZeroRadius, Error, "error", "radius below 0.00127 mm (I J read as incremental when the program wrote absolute centres: the help says so)") \
  X(306, UpperArcOffCircle, Error, "error", "xyuv-rel: the upper arc from U V and K L ends off its circle") \
  X(307, CountContradicts, Error, "error/note", "a 3B J that its x y or count axis contradict (note: an arc counted along the slower axis)") \
  X(308, CountPastFullCircle, Error, "error", "a 3B arc J longer than a full circle") \
  /* Motion */ \
  X(402, ZeroLengthMove, Warning, "warning", "a cutting move of zero length") \
  /* Program flow and subprograms */ \
  X(501, CallWithoutProgram, Error, "error", "M98 without P") \
  X(502, SubprogramNotFound, Error, "error", "M98 P<n> with no O<n> or N<n>") \
  X(503, CallTooDeep, Error, "error", "subprogram calls nested deeper than 16") \
  X(504, ReturnOutsideSubprogram, Warning, "warning", "M99 in the main program (ends it)") \
  X(505, MissingProgramEnd, Warning, "warning/note", "no M02/M30, or a subprogram without M99; note: a 3B program without its end mark (DD), which some controls do not need") \
  X(506, BadRepeatCount, Error, "error", "L not a whole number 1–9999") \
  X(507, ExecutionLimit, Error, "error", "too many executed blocks or moves (endless loops, repeat bombs)") \
  X(508, DuplicateLabel, Warning, "warning", "the same O number twice") \
  /* Geometry of the cut path */ \
  X(601, PathCrossesItself, Error, "error", "the cut path crosses itself") \
  X(602, PathTouchesItself, Error, "error", "an end point of one move lies on another move and the cut goes on (a pinch)") \
  X(603, PathOverlapsItself, Error, "error", "the cut path runs over itself, or folds back") \
  X(604, PathRetraces, Note, "note", "the lead-out runs back along the lead-in") \
  X(605, PathOpen, Warning, "warning", "the cut path never closes a loop") \
  X(606, NothingCut, Error, "error", "nothing to cut: the file holds no program, no 3B record or no drawing element (at 1:1), or the program cuts nothing (at its first move)") \
  X(607, RapidInsideCut, Warning, "warning/note", "a rapid between cuts (a point-driven machine would cut along it); note: the same with a stop (M00, M01, a profile's `rethread` code) between the cuts on either side, where the wire is cut and threaded again") \
  X(608, LoopClosesInsideMove, Note, "note", "the contour closes where one move meets another inside it, and nothing but the way back follows: as if the block were split there (IGK1, STAR5)") \
  X(609, TaperSeam, Note, "note", "a taper starts and ends at the same point, so the wire passes it twice leaning two ways") \
  /* Passes over one contour (docs/passes.md) */ \
  X(610, PassWrongSide, Error, "error", "a pass runs on the other side of its programmed contour from the contour's first pass (G41/G42 and the direction of travel say which side): it cuts into what that pass kept") \
  X(611, OffsetGrows, Warning, "warning", "a skim's offset is larger than the offset of the pass before it: it runs outside the path already cut and removes nothing") \
  X(612, PartFallsBeforeSkims, Warning, "warning", "a punch is cut free by a pass that closes its contour while skims of it follow: they skim a part that has fallen (leave a tab and cut it off last)") \
  X(613, CutOffWithoutStop, Warning, "warning", "a cut-off through the tab with no stop (M00, M01, a profile's `rethread` code) since the pass before it: the slug or part is not secured when it falls") \
  X(614, SlugFalls, Note, "note", "where a die's slug falls free: the end of the first pass that closes its contour") \
  X(630, DrawingElementOff, Error, "error", "`--drawing`: a drawing element is cut farther off than `--drawing-tolerance` (at the nearest block, with the deviation and where)") \
  X(631, DrawingContourNotCut, Error, "error", "`--drawing`: a closed contour of the drawing that no move comes near (a hole or outline not cut)") \
  X(632, CutNotInDrawing, Warning, "warning", "`--drawing`: moves that cut what the drawing does not have (one finding per run of them)") \
  X(633, DrawingWireCentre, Note, "note", "`--drawing`: passes cut with no G41/G42 in force are the wire's path: moved back by `--offset` (to `--side`, or to the side nearer the drawing), or compared as written") \
  X(634, DrawingPlacedOtherwise, Error, "error/note", "`--drawing`: the program cuts the drawing turned, shifted or mirrored (named); a note with `--align` unless mirrored") \
  X(635, DrawingEmpty, Error, "error", "`--drawing`: the drawing (or the layer named) holds no line, arc or curve to compare the program with; the help names the layers that do") \
  /* Geometry of the ruled surface (4-axis taper) */ \
  X(650, TaperTooSteep, Error, "error", "the wire's slope exceeds `--max-taper` (default 30°)") \
  X(651, SurfaceSelfIntersection, Error, "error", "two patches that are not neighbours meet between the planes (sampled in z)") \
  X(652, WireCrossing, Error, "error", "positions of the wire in one patch, or in neighbouring patches, cross") \
  X(653, PatchTwisted, Error, "error", "the upper direction of travel turns more than 90° from the lower one") \
  X(654, SurfaceFold, Error, "error", "neighbouring patches fold onto each other at their joint") \
  X(655, ClosureMismatch, Error, "error", "one contour closes a loop and the other does not") \
  X(656, UvOutOfRange, Error, "error", "\\|upper − lower\\| along X or Y beyond `--uv-range`") \
  X(657, SectionsCoarsened, Note, "note", "the surface's sections would need more pieces than `CheckOptions::sectionBudget` (100,000 a section); the twisted patches are tested as coarser polylines, so a crossing closer than their chord error may be missed") \
  /* Numbers */ \
  X(701, IntegerUnitSuspect, Warning, "warning", "integers only, and large: perhaps micrometres") \
  /* Outputs and options */ \
  X(801, CapacityTooSmall, Error, "error", "no sampling fits `--max-points`, or the step gives more than 50,000,000 points") \
  X(802, ProfileError, Error, "error", "a bad line in a point profile file") \
  X(803, StartBlockNotFound, Error, "error/warning", "`--start-block` names no cutting move, or drops moves of an open path") \
  X(804, TaperFlattened, Warning, "warning/error", "a taper program written for a 2-axis machine at one plane; error: `z=` outside the part") \
  X(805, PolarThroughCentre, Error, "error", "a move through the face centre cannot be written as X/C") \
  X(806, NotInOutputFormat, Warning, "warning/note", "something the output format cannot say (3B rapids, M101 and a lower plane); note: G41/G42 written without their value, which the machine holds") \
  X(807, OutputAdjusted, Note, "note/warning", "a 3B arc centre moved, or a count that misses its grid point") \
  X(808, OutputUnsure, Note, "note", "the 4B layout is unsure") \
  X(809, OutputExpanded, Note, "note", "subprogram calls and repeats written out in a converted program") \
  X(810, MachineProfileError, Error, "error", "a wrong line in a machine profile file, or an unknown profile name") \
  X(811, OffsetTableError, Error, "error", "a wrong line in an `--offsets` table: not `H001 = 0.180`, a value that is no offset from 0 to 10 mm, a register given twice") \
  X(812, GuidesUnknown, Error, "error", "`--plane guides` (the wire at its guides) where no guide heights are given: `--guides`, cnc3's `M100 P Q` or the profile's `guides`") \
  X(813, NothingToWrite, Error, "error", "a writer has nothing it can write: no move (ISO, polar X/C) or no cutting move (3B, 4B, points)") \
  X(814, OptionDoesNotFit, Error, "error", "an option the input cannot take: `--drawing-upper` for a 2-axis program, `--drawing-upper-layer` with no `--drawing`, `--contour N` past the drawing's contours, `--entry` with several contours, `--to points4` for a program with no upper contour") \
  X(899, TooManyDiagnostics, Warning, "warning", "more self-intersections than reported") \
  /* The wire offset (G41/G42 applied to the program, and kerf cam's offset of a drawing) */ \
  X(901, WireOffsetApplied, Note, "note", "the wire offset was applied (the side and value of the first run, on which planes): checks, pictures and outputs use the wire-centre path") \
  X(902, WireCannotReach, Warning, "warning", "elements of a contour the wire path cannot reach at all (a slot or recess narrower than the wire), with how much material stays and where") \
  X(903, InsideCornerRadius, Note, "note", "an inside corner whose radius is smaller than the wire offset: the wire cuts it with its own radius") \
  X(904, WirePathSplits, Warning, "warning/error", "a contour's wire path splits into several loops (it narrows below the wire's width); error: nothing is left (the contour is smaller than the wire)") \
  X(905, WireOffsetRefused, Error, "error", "the wire offset would need more pieces than the budget allows; nothing is computed")
// clang-format on
