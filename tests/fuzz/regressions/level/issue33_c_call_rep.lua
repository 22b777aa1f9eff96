-- Issue 33: one C call that ran for hours inside the VM's single instruction.
local s = string.rep('', math.maxinteger)
return { name = "x" }
